#pragma once
// Where a robot's centre is, as objectives and mission rules ask it: a floor Region (disc,
// rectangle, polygon), a ring around a circle (SPC's "on the perimeter"), or axis-aligned
// limits (half-planes and their intersections: the foraging nest y <= -0.6, the SCA shelter
// with strict bounds). Robot centres are tested, never bodies, as the loop functions do.
#include <limits>
#include <variant>
#include <vector>

#include "simulator/region.hpp"

namespace sd {

/// Points whose distance to `center` differs from `radius` by at most `half_width`.
struct Ring {
  Vec2 center;
  double radius = 0.0;
  double half_width = 0.0;
  bool contains(Vec2 p) const {
    const double d = (p - center).length() - radius;
    return d <= half_width && d >= -half_width;
  }
};

/// x_min <= x <= x_max and y_min <= y <= y_max (strict: < instead of <=); absent limits are
/// infinite.
struct Limits {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  double x_min = -kNone, x_max = kNone, y_min = -kNone, y_max = kNone;
  bool strict = false;
  bool contains(Vec2 p) const {
    if (strict) return p.x > x_min && p.x < x_max && p.y > y_min && p.y < y_max;
    return p.x >= x_min && p.x <= x_max && p.y >= y_min && p.y <= y_max;
  }
};

using Zone = std::variant<Region, Ring, Limits>;

inline bool zone_contains(const Zone& zone, Vec2 p) {
  return std::visit([p](const auto& z) { return z.contains(p); }, zone);
}

/// Which robots a measure looks at: all, those in a zone, or those in none of some zones.
struct RobotFilter {
  enum class Kind { All, InZone, OutsideZones };
  Kind kind = Kind::All;
  std::vector<Zone> zones;
  bool accepts(Vec2 p) const {
    switch (kind) {
      case Kind::All:
        return true;
      case Kind::InZone:
        return zone_contains(zones.front(), p);
      case Kind::OutsideZones:
        for (const Zone& z : zones)
          if (zone_contains(z, p)) return false;
        return true;
    }
    return true;
  }
};

}  // namespace sd
