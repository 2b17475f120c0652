#include "missions/objective_network_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "missions/read_shapes.hpp"

namespace sd {

NetworkCoverageObjective read_network_coverage(const Field& f) {
  f.only({"type", "direction", "link_range", "sensing_range", "clip", "samples_per_m2", "box_max_from_zero"});
  NetworkCoverageObjective o;
  o.link_range = f.at("link_range").positive();
  o.sensing_range = f.at("sensing_range").positive();
  o.clip = read_zone(f.at("clip"));
  o.samples_per_m2 = f.at("samples_per_m2").positive();
  if (o.samples_per_m2 > 1e7) f.at("samples_per_m2").fail("must be at most 10^7");
  o.box_max_from_zero = f.boolean_or("box_max_from_zero", false);
  return o;
}

NetworkCoverageScore::NetworkCoverageScore(const NetworkCoverageObjective& params, RunContext run)
    : params_(&params), run_(run) {
  const auto n = static_cast<std::size_t>(run.robots);
  label_.resize(n);
  stack_.reserve(n);
  group_.reserve(n);
}

const std::vector<Vec2>& NetworkCoverageScore::largest_component(const SwarmState& swarm) {
  const auto n = static_cast<std::size_t>(swarm.size);
  const double link_sq = params_->link_range * params_->link_range;
  std::fill(label_.begin(), label_.end(), -1);
  std::int32_t labels = 0, best_label = -1;
  std::size_t best_size = 0;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (label_[seed] >= 0) continue;
    const std::int32_t label = labels++;
    std::size_t size = 0;
    label_[seed] = label;
    stack_.push_back(static_cast<std::uint16_t>(seed));
    while (!stack_.empty()) {
      const std::size_t a = stack_.back();
      stack_.pop_back();
      ++size;
      for (std::size_t b = 0; b < n; ++b)
        if (label_[b] < 0 && (swarm.position[a] - swarm.position[b]).squared_length() < link_sq) {
          label_[b] = label;
          stack_.push_back(static_cast<std::uint16_t>(b));
        }
    }
    if (size > best_size) {  // strict: ties keep the first component found
      best_size = size;
      best_label = label;
    }
  }
  group_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (label_[i] == best_label) group_.push_back(swarm.position[i]);
  return group_;
}

double NetworkCoverageScore::covered_area(Rng& rng) const {
  if (group_.empty()) return 0.0;
  const double s = params_->sensing_range;
  constexpr double kHuge = std::numeric_limits<double>::max();
  Vec2 lo{kHuge, kHuge};
  Vec2 hi = params_->box_max_from_zero ? Vec2{0.0, 0.0} : Vec2{-kHuge, -kHuge};
  for (const Vec2 p : group_) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  lo = lo - Vec2{s, s};
  hi = hi + Vec2{s, s};
  const double box_area = (hi.x - lo.x) * (hi.y - lo.y);
  const auto n = static_cast<long long>(std::ceil(box_area * params_->samples_per_m2));
  const double s_sq = s * s;
  long long covered = 0;
  for (long long k = 0; k < n; ++k) {
    const double x = rng.uniform(lo.x, hi.x);
    const Vec2 q{x, rng.uniform(lo.y, hi.y)};
    if (!zone_contains(params_->clip, q)) continue;
    for (const Vec2 p : group_)
      if ((p - q).squared_length() <= s_sq) {
        ++covered;
        break;
      }
  }
  return box_area * static_cast<double>(covered) / static_cast<double>(n);
}

void NetworkCoverageScore::post_step(const SwarmState& swarm, int tick, Rng& rng) {
  if (tick != run_.ticks) return;  // PostExperiment: the final positions only
  largest_component(swarm);
  value_ = covered_area(rng);
}

}  // namespace sd
