#include "simulator/region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math.hpp"

namespace sd {

Region Region::circle(Vec2 c, double r, bool inclusive) {
  Region region;
  region.shape = Shape::Circle;
  region.center = c;
  region.radius = r;
  region.inclusive = inclusive;
  return region;
}

Region Region::rectangle(Vec2 c, Vec2 size, double yaw) {
  Region region;
  region.shape = Shape::Rectangle;
  region.center = c;
  region.half_size = size * 0.5;
  region.yaw = yaw;
  return region;
}

Region Region::polygon(std::vector<Vec2> vertices) {
  Region region;
  region.shape = Shape::Polygon;
  region.vertices = std::move(vertices);
  return region;
}

bool Region::contains_other(Vec2 p) const {
  switch (shape) {
    case Shape::Circle: {
      const double d2 = (p - center).squared_length();
      return inclusive ? d2 <= radius * radius : d2 < radius * radius;
    }
    case Shape::Rectangle: {
      const Vec2 d = p - center;
      const auto [s, c] = math::sincos(yaw);
      const double lx = c * d.x + s * d.y, ly = -s * d.x + c * d.y;
      return std::abs(lx) <= half_size.x && std::abs(ly) <= half_size.y;
    }
    case Shape::Polygon: {
      // Even-odd crossing test.
      bool inside = false;
      const std::size_t n = vertices.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2 a = vertices[i], b = vertices[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
      }
      return inside;
    }
  }
  return false;
}

double Region::boundary_distance(Vec2 p) const {
  switch (shape) {
    case Shape::Circle:
      return std::abs((p - center).length() - radius);
    case Shape::Rectangle: {
      const Vec2 d = p - center;
      const auto [s, c] = math::sincos(yaw);
      const double ex = std::abs(c * d.x + s * d.y) - half_size.x, ey = std::abs(-s * d.x + c * d.y) - half_size.y;
      if (ex <= 0.0 && ey <= 0.0) return std::min(-ex, -ey);
      return Vec2{std::max(ex, 0.0), std::max(ey, 0.0)}.length();
    }
    case Shape::Polygon: {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++)
        best = std::min(best, distance_to_segment(p, vertices[j], vertices[i]));
      return best;
    }
  }
  return 0.0;
}

std::pair<Vec2, Vec2> Region::bounds() const {
  switch (shape) {
    case Shape::Circle:
      return {center - Vec2{radius, radius}, center + Vec2{radius, radius}};
    case Shape::Rectangle: {
      const math::SinCos sc = math::sincos(yaw);
      const double c = std::abs(sc.cos), s = std::abs(sc.sin);
      const Vec2 e{c * half_size.x + s * half_size.y, s * half_size.x + c * half_size.y};
      return {center - e, center + e};
    }
    case Shape::Polygon: {
      Vec2 lo = vertices.front(), hi = vertices.front();
      for (const Vec2 v : vertices) {
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
      }
      return {lo, hi};
    }
  }
  return {};
}

double Region::area() const {
  switch (shape) {
    case Shape::Circle:
      return kPi * radius * radius;
    case Shape::Rectangle:
      return 4.0 * half_size.x * half_size.y;
    case Shape::Polygon: {
      double a = 0.0;
      for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) a += cross(vertices[j], vertices[i]);
      return std::abs(a) * 0.5;
    }
  }
  return 0.0;
}

}  // namespace sd
