#include "simulator/robot_deviations.hpp"

#include "core/rng.hpp"

namespace sd {

namespace {

// Mixed into the run's seed so the deviations' stream is not the run's own.
constexpr std::uint64_t kDeviationStream = 0x6465766961746521ull;  // "deviate!"

void draw_gains(std::vector<double>& gains, int robots, double deviation, double scale, Rng& rng) {
  gains.resize(static_cast<std::size_t>(robots));
  // One draw per robot even at 0 (a gain of exactly 1): the kinds drawn after this one get the
  // same gains whether or not this one deviates.
  for (double& g : gains) g = scale * rng.uniform(1.0 - deviation, 1.0 + deviation);
}

}  // namespace

void RobotDeviations::draw(const RobotModel& model, int robots, std::uint64_t seed) {
  active = model.has_deviations();
  if (!active) return;
  Rng rng(seed ^ kDeviationStream);
  // Always in this order and for every kind, so a robot's wheel gains do not depend on
  // whether its light gain is drawn.
  draw_gains(wheel_left, robots, model.wheel_deviation, 1.0, rng);
  draw_gains(wheel_right, robots, model.wheel_deviation, 1.0, rng);
  draw_gains(proximity, robots, model.proximity_deviation, 1.0, rng);
  draw_gains(light, robots, model.light_deviation, 1.0, rng);
  draw_gains(rab_range, robots, model.rab_range_deviation, model.rab_range, rng);
}

}  // namespace sd
