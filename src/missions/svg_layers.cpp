#include "missions/svg_layers.hpp"

#include <algorithm>
#include <sstream>
#include <variant>

namespace sd {

namespace {

constexpr const char* kZoneStyle =
    "fill=\"none\" stroke=\"#7b2cbf\" stroke-width=\"0.01\" stroke-dasharray=\"0.03 0.02\" class=\"zone\"";

std::string region_outline(const Region& r) {
  std::ostringstream out;
  switch (r.shape) {
    case Region::Shape::Circle:
      out << "<circle cx=\"" << r.center.x << "\" cy=\"" << r.center.y << "\" r=\"" << r.radius << "\" " << kZoneStyle << "/>";
      break;
    case Region::Shape::Rectangle:
      out << "<rect x=\"" << -r.half_size.x << "\" y=\"" << -r.half_size.y << "\" width=\"" << 2 * r.half_size.x
          << "\" height=\"" << 2 * r.half_size.y << "\" transform=\"translate(" << r.center.x << " " << r.center.y
          << ") rotate(" << r.yaw * 180.0 / kPi << ")\" " << kZoneStyle << "/>";
      break;
    case Region::Shape::Polygon:
      out << "<polygon points=\"";
      for (const Vec2 v : r.vertices) out << v.x << "," << v.y << " ";
      out << "\" " << kZoneStyle << "/>";
      break;
  }
  return out.str();
}

std::string zone_outline(const Zone& zone, Vec2 lo, Vec2 hi) {
  std::ostringstream out;
  if (const auto* region = std::get_if<Region>(&zone)) return region_outline(*region);
  if (const auto* ring = std::get_if<Ring>(&zone)) {
    for (const double r : {ring->radius - ring->half_width, ring->radius + ring->half_width})
      out << "<circle cx=\"" << ring->center.x << "\" cy=\"" << ring->center.y << "\" r=\"" << r << "\" " << kZoneStyle << "/>";
    return out.str();
  }
  const Limits& l = std::get<Limits>(zone);  // a half-plane or box: drawn within the picture
  const double x0 = std::max(l.x_min, lo.x), x1 = std::min(l.x_max, hi.x);
  const double y0 = std::max(l.y_min, lo.y), y1 = std::min(l.y_max, hi.y);
  if (x1 > x0 && y1 > y0)
    out << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << x1 - x0 << "\" height=\"" << y1 - y0 << "\" " << kZoneStyle << "/>";
  return out.str();
}

std::string grid(const GridExplorationObjective& g) {
  std::ostringstream out;
  const double half = g.side / 2, step = g.side / g.cells;
  out << "<g class=\"grid\" stroke=\"#5a6470\" stroke-width=\"0.006\" stroke-opacity=\"0.7\">";
  for (int k = 0; k <= g.cells; ++k) {
    const double at = -half + k * step;
    out << "<line x1=\"" << g.center.x + at << "\" y1=\"" << g.center.y - half << "\" x2=\"" << g.center.x + at << "\" y2=\""
        << g.center.y + half << "\"/>";
    out << "<line x1=\"" << g.center.x - half << "\" y1=\"" << g.center.y + at << "\" x2=\"" << g.center.x + half << "\" y2=\""
        << g.center.y + at << "\"/>";
  }
  out << "</g>";
  return out.str();
}

}  // namespace

std::vector<Vec2> arena_outline(const Mission& m) {
  std::vector<Vec2> points;
  for (const Wall& w : m.arena.walls) {
    const Vec2 along = w.axis * w.half_length, across = Vec2{-w.axis.y, w.axis.x} * w.half_thickness;
    for (const Vec2 p : {w.center + along + across, w.center + along - across, w.center - along + across, w.center - along - across})
      points.push_back(p);
  }
  if (points.size() < 3) return {};
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::string objective_layer(const Mission& m, Vec2 lo, Vec2 hi) {
  std::ostringstream out;
  std::visit(
      [&](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, GridExplorationObjective>) out << grid(p);
        if constexpr (std::is_same_v<P, RegionCountObjective>) out << zone_outline(p.zone, lo, hi);
        if constexpr (std::is_same_v<P, BestRegionObjective>)
          for (const Zone& z : p.regions) out << zone_outline(z, lo, hi);
        if constexpr (std::is_same_v<P, ForagingObjective>) {
          for (const auto& s : p.sources) out << zone_outline(s.zone, lo, hi);
          out << zone_outline(p.nest, lo, hi);
        }
      },
      m.objective.parameters);
  return out.str();
}

}  // namespace sd
