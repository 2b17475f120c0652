#include "evostick/training_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "simulator/epuck.hpp"

namespace sd::evostick {

namespace {

// Coverage grid: 10 cm cells over a 3 m x 3 m square centred on the origin, which holds the
// AAC dodecagon (apothem 1.231 m); a robot outside it counts in the border cell.
constexpr double kCellSize = 0.1;
constexpr int kCellsPerSide = 30;
constexpr double kGridHalfSide = kCellSize * kCellsPerSide / 2.0;

int cell_of(Vec2 p) {
  const auto index = [](double v) {
    return std::clamp(static_cast<int>(std::floor((v + kGridHalfSide) / kCellSize)), 0, kCellsPerSide - 1);
  };
  return index(p.y) * kCellsPerSide + index(p.x);
}

}  // namespace

std::string_view measure_name(Measure measure) {
  switch (measure) {
    case Measure::Coverage: return "coverage";
    case Measure::Stillness: return "stillness";
    case Measure::LightApproach: return "light-approach";
    case Measure::LightAvoidance: return "light-avoidance";
    case Measure::Cohesion: return "cohesion";
    case Measure::Dispersion: return "dispersion";
  }
  return "unknown";
}

std::string_view measure_description(Measure measure) {
  switch (measure) {
    case Measure::Coverage:
      return "mean over robots of the 10 x 10 cm floor cells the robot's centre has visited (more is better)";
    case Measure::Stillness:
      return "minus the mean distance a robot's wheels roll during the run (mean of the two wheels), in m; "
             "spinning in place or pushing against a wall counts as moving (0 is best)";
    case Measure::LightApproach:
      return "minus the mean over ticks and robots of the horizontal distance to the light, in m";
    case Measure::LightAvoidance:
      return "mean over ticks and robots of the horizontal distance to the light, in m";
    case Measure::Cohesion:
      return "minus the mean over ticks and robots of the distance to the swarm's centroid, in m";
    case Measure::Dispersion:
      return "mean over ticks and robots of the distance to the nearest other robot, in m";
  }
  return "";
}

MeasureObserver::MeasureObserver(Measure measure, const Mission& mission) : measure_(measure) {
  if (measure == Measure::LightApproach || measure == Measure::LightAvoidance) {
    if (mission.arena.lights.empty())
      throw std::invalid_argument("mission '" + mission.name + "' has no light for the " +
                                  std::string(measure_name(measure)) + " measure");
    light_ = mission.arena.lights.front().position.xy();
  }
}

void MeasureObserver::start(const SwarmState& swarm) {
  robots_ = swarm.size;
  sum_ = 0.0;
  ticks_ = 0;
  visited_.assign(static_cast<std::size_t>(robots_) * kCellsPerSide * kCellsPerSide, 0);
  visited_count_ = 0;
}

void MeasureObserver::on_tick(const Simulation& simulation) {
  const SwarmState& swarm = simulation.swarm();
  if (simulation.tick() == 0) start(swarm);  // placement; every run of a Simulation starts here
  const auto n = static_cast<std::size_t>(robots_);
  if (measure_ == Measure::Coverage) {
    // The start cell counts: it is visited, and counting it keeps every robot at >= 1.
    for (std::size_t i = 0; i < n; ++i) {
      unsigned char& cell = visited_[i * kCellsPerSide * kCellsPerSide + static_cast<std::size_t>(cell_of(swarm.position[i]))];
      visited_count_ += cell == 0;
      cell = 1;
    }
    return;
  }
  if (simulation.tick() == 0) return;
  ++ticks_;
  double tick_sum = 0.0;
  switch (measure_) {
    case Measure::Stillness:
      // The wheels, not the body: spinning in place or pushing against a wall is not stopping.
      for (std::size_t i = 0; i < n; ++i)
        tick_sum += 0.5 * (std::abs(swarm.wheel_left[i]) + std::abs(swarm.wheel_right[i])) * epuck::kTickSeconds;
      break;
    case Measure::LightApproach:
    case Measure::LightAvoidance:
      for (std::size_t i = 0; i < n; ++i) tick_sum += (swarm.position[i] - light_).length();
      break;
    case Measure::Cohesion: {
      Vec2 centroid;
      for (std::size_t i = 0; i < n; ++i) centroid += swarm.position[i];
      centroid = centroid * (1.0 / static_cast<double>(n));
      for (std::size_t i = 0; i < n; ++i) tick_sum += (swarm.position[i] - centroid).length();
      break;
    }
    case Measure::Dispersion:
      for (std::size_t i = 0; i < n; ++i) {
        double nearest_sq = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < n; ++j)
          if (j != i) nearest_sq = std::min(nearest_sq, (swarm.position[j] - swarm.position[i]).squared_length());
        tick_sum += n > 1 ? std::sqrt(nearest_sq) : 0.0;
      }
      break;
    case Measure::Coverage:
      break;
  }
  sum_ += tick_sum / static_cast<double>(n);
}

double MeasureObserver::value() const {
  if (robots_ == 0) return 0.0;
  switch (measure_) {
    case Measure::Coverage: return static_cast<double>(visited_count_) / static_cast<double>(robots_);
    case Measure::Stillness: return -sum_;  // the per-tick means add up to the mean rolled distance
    case Measure::LightApproach:
    case Measure::Cohesion: return ticks_ > 0 ? -sum_ / ticks_ : 0.0;
    case Measure::LightAvoidance:
    case Measure::Dispersion: return ticks_ > 0 ? sum_ / ticks_ : 0.0;
  }
  return 0.0;
}

}  // namespace sd::evostick
