#include "missions/objective_mean_distance.hpp"

#include <algorithm>
#include <cmath>

#include "missions/read_shapes.hpp"
#include "simulator/placement.hpp"

namespace sd {

namespace {

PointSampler read_points(const Field& f) {
  f.single_key("polar_disc, on_circle, uniform_in");
  PointSampler s;
  if (f.has("uniform_in")) {
    s.kind = PointSampler::Kind::UniformIn;
    s.region = read_region(f.at("uniform_in"));
    return s;
  }
  const bool polar = f.has("polar_disc");
  if (!polar && !f.has("on_circle")) f.fail("expected one of polar_disc, on_circle, uniform_in");
  const Field c = f.at(polar ? "polar_disc" : "on_circle");
  c.only({"center", "radius"});
  s.kind = polar ? PointSampler::Kind::PolarDisc : PointSampler::Kind::OnCircle;
  s.region = Region::circle(c.at("center").vec2(), c.at("radius").positive());
  return s;
}

}  // namespace

Vec2 PointSampler::draw(Rng& rng) const {
  switch (kind) {
    case Kind::PolarDisc: {
      const double rho = rng.uniform(0.0, region.radius);
      return region.center + Vec2::polar(rho, rng.uniform(0.0, kTwoPi));
    }
    case Kind::OnCircle:
      return region.center + Vec2::polar(region.radius, rng.uniform(0.0, kTwoPi));
    case Kind::UniformIn:
      return sample_point(region, rng);
  }
  return region.center;
}

MeanDistanceObjective read_mean_distance(const Field& f) {
  f.only({"type", "direction", "terms", "offset", "at_least"});
  MeanDistanceObjective o;
  const Field terms = f.at("terms");
  if (terms.items() == 0) terms.fail("give at least one term");
  for (std::size_t i = 0; i < terms.items(); ++i) {
    const Field t = terms.at(i);
    t.only({"points", "count", "robots", "missing_distance", "weight", "normalizer"});
    MeanDistanceTerm term;
    term.points = read_points(t.at("points"));
    term.count = t.at("count").integer_in(1, 10'000'000);
    term.robots = read_robot_filter(t, "robots");
    term.missing_distance = t.at("missing_distance").non_negative();
    term.weight = t.number_or("weight", 1.0);
    term.normalizer = t.positive_or("normalizer", 1.0);
    o.terms.push_back(std::move(term));
  }
  o.offset = f.number_or("offset", 0.0);
  o.at_least = f.number_or("at_least", o.at_least);
  return o;
}

MeanDistanceScore::MeanDistanceScore(const MeanDistanceObjective& params, RunContext run)
    : params_(&params), run_(run) {
  selected_.reserve(static_cast<std::size_t>(run.robots));
}

double MeanDistanceScore::mean_distance(const MeanDistanceTerm& term, const SwarmState& swarm, Rng& rng) {
  selected_.clear();  // keeps its capacity: no allocation
  for (int i = 0; i < swarm.size; ++i)
    if (term.robots.accepts(swarm.position[static_cast<std::size_t>(i)])) selected_.push_back(swarm.position[static_cast<std::size_t>(i)]);
  double sum = 0.0;
  for (int k = 0; k < term.count; ++k) {
    const Vec2 q = term.points.draw(rng);  // drawn even when no robot counts, as the original
    if (selected_.empty()) {
      sum += term.missing_distance;
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Vec2 p : selected_) best = std::min(best, (p - q).squared_length());
    sum += std::sqrt(best);
  }
  return sum / term.count;
}

void MeanDistanceScore::post_step(const SwarmState& swarm, int tick, Rng& rng) {
  if (tick != run_.ticks) return;  // PostExperiment: the final positions only
  double f = params_->offset;
  for (const MeanDistanceTerm& term : params_->terms) f += term.weight * mean_distance(term, swarm, rng) / term.normalizer;
  value_ = std::max(params_->at_least, f);
}

}  // namespace sd
