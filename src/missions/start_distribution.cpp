#include "missions/start_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "missions/json_field.hpp"
#include "missions/mission.hpp"
#include "simulator/placement.hpp"

namespace sd {

Vec2 JitteredArc::draw(Rng& rng) const {
  double a = rng.uniform(), b = rng.uniform();
  if (b < a) std::swap(a, b);
  const double c = rng.uniform(-1.0, 1.0), d = rng.uniform(-1.0, 1.0);
  const double phi = from + span * (b > 0.0 ? a / b : 0.0);
  return center + Vec2{jitter * c, jitter * d} + Vec2::polar(radius, phi);
}

Region JitteredArc::support() const {
  // The arc's own bounds: its two ends and every axis direction it sweeps through.
  const double lo_angle = std::min(from, from + span), hi_angle = std::max(from, from + span);
  Vec2 lo = Vec2::polar(radius, lo_angle), hi = lo;
  auto grow = [&](double angle) {
    const Vec2 p = Vec2::polar(radius, angle);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  };
  grow(hi_angle);
  // NOLINTNEXTLINE(cert-flp30-c): at most five quarter turns; changing the sum would move starts
  for (double a = std::ceil(lo_angle / (kPi / 2)) * (kPi / 2); a < hi_angle; a += kPi / 2) grow(a);
  const Vec2 margin{jitter, jitter};
  lo = lo - margin;
  hi = hi + margin;
  return Region::rectangle(center + (lo + hi) * 0.5, hi - lo);
}

Vec2 Mission::draw_start(Rng& rng) const { return start_arc ? start_arc->draw(rng) : sample_point(start, rng); }

std::optional<JitteredArc> read_jittered_arc(const Field& f) {
  if (!f.has("jittered_arc")) return std::nullopt;
  f.only({"jittered_arc"});
  const Field a = f.at("jittered_arc");
  a.only({"center", "radius", "jitter", "from", "span"});
  JitteredArc arc;
  arc.center = a.at("center").vec2();
  arc.radius = a.at("radius").non_negative();
  arc.jitter = a.at("jitter").non_negative();
  if (arc.radius + arc.jitter <= 0.0) a.fail("radius and jitter cannot both be 0");
  arc.from = degrees_to_radians(a.number_or("from", 0.0));
  arc.span = degrees_to_radians(a.number_or("span", 360.0));
  return arc;
}

}  // namespace sd
