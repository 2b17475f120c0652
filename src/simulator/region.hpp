#pragma once
// A region of the floor: disc, rectangle (optionally rotated) or convex/concave polygon.
// Floor patches, start regions and objective regions are all Regions.
#include <string>
#include <vector>

#include "core/geometry.hpp"

namespace sd {

struct Region {
  enum class Shape { Circle, Rectangle, Polygon };
  Shape shape = Shape::Circle;
  Vec2 center;                  // circle, rectangle
  double radius = 0.0;          // circle
  Vec2 half_size;               // rectangle, in its own frame
  double yaw = 0.0;             // rectangle rotation (rad)
  std::vector<Vec2> vertices;   // polygon, in order
  bool inclusive = true;        // circle: distance <= r (true) or < r (false)

  static Region circle(Vec2 center, double radius, bool inclusive = true);
  static Region rectangle(Vec2 center, Vec2 size, double yaw = 0.0);
  static Region polygon(std::vector<Vec2> vertices);

  bool contains(Vec2 p) const {
    if (shape == Shape::Circle) {  // the common case, inline
      const double d2 = (p - center).squared_length();
      return inclusive ? d2 <= radius * radius : d2 < radius * radius;
    }
    return contains_other(p);
  }
  /// Distance from p to the region's edge, whether p is inside or outside.
  double boundary_distance(Vec2 p) const;
  /// Axis-aligned bounds (min, max).
  std::pair<Vec2, Vec2> bounds() const;
  double area() const;

 private:
  bool contains_other(Vec2 p) const;
};

}  // namespace sd
