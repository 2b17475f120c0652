#include "missions/read_shapes.hpp"

#include <string>

namespace sd {

namespace {

struct NamedColor {
  const char* name;
  std::uint32_t rgb;
};
// ARGoS' named colours; gray is GRAY50.
constexpr NamedColor kColors[] = {{"black", 0x000000}, {"white", 0xffffff}, {"gray", 0x7f7f7f},
                                  {"red", 0xff0000},   {"green", 0x00ff00}, {"blue", 0x0000ff},
                                  {"yellow", 0xffff00}, {"magenta", 0xff00ff}, {"cyan", 0x00ffff}};

}  // namespace

std::uint32_t read_color(const Field& f) {
  const std::string name = f.text();
  for (const auto& c : kColors)
    if (name == c.name) return c.rgb;
  if (name.size() == 7 && name[0] == '#' && name.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos)
    return static_cast<std::uint32_t>(std::stoul(name.substr(1), nullptr, 16));
  f.fail("unknown colour '" + name + "' (black, white, gray, red, green, blue, yellow, magenta, cyan or #rrggbb)");
}

double gray_of(std::uint32_t rgb) {
  // Ground sensor: 0.299 R + 0.587 G + 0.114 B, over 255 (ARGoS ToGrayScale).
  const double r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
  return (0.299 * r + 0.587 * g + 0.114 * b) / 255.0;
}

Region read_region(const Field& f) {
  const std::string kind = f.single_key("circle, rectangle, polygon");
  if (kind == "circle") {
    const Field c = f.at("circle");
    c.only({"center", "radius", "inclusive"});
    return Region::circle(c.at("center").vec2(), c.at("radius").positive(), c.boolean_or("inclusive", true));
  }
  if (kind == "rectangle") {
    const Field r = f.at("rectangle");
    r.only({"center", "size", "yaw"});
    const Vec2 size = r.at("size").vec2();
    if (size.x <= 0 || size.y <= 0) r.at("size").fail("sizes must be positive");
    return Region::rectangle(r.at("center").vec2(), size, degrees_to_radians(r.number_or("yaw", 0.0)));
  }
  if (kind == "polygon") {
    const Field p = f.at("polygon");
    std::vector<Vec2> vertices;
    for (std::size_t i = 0; i < p.items(); ++i) vertices.push_back(p.at(i).vec2());
    if (vertices.size() < 3) p.fail("a polygon needs at least 3 vertices");
    Region region = Region::polygon(std::move(vertices));
    if (region.area() <= 0.0) p.fail("the polygon has no area");
    return region;
  }
  f.at(kind).fail("unknown shape (expected circle, rectangle or polygon)");
}

Zone read_zone(const Field& f) {
  const std::string kind = f.single_key("circle, rectangle, polygon, ring, limits");
  if (kind == "ring") {
    const Field r = f.at("ring");
    r.only({"center", "radius", "half_width"});
    return Ring{r.at("center").vec2(), r.at("radius").positive(), r.at("half_width").positive()};
  }
  if (kind == "limits") {
    const Field l = f.at("limits");
    l.only({"x_min", "x_max", "y_min", "y_max", "strict"});
    Limits limits;
    limits.x_min = l.number_or("x_min", limits.x_min);
    limits.x_max = l.number_or("x_max", limits.x_max);
    limits.y_min = l.number_or("y_min", limits.y_min);
    limits.y_max = l.number_or("y_max", limits.y_max);
    limits.strict = l.boolean_or("strict", false);
    if (!l.has("x_min") && !l.has("x_max") && !l.has("y_min") && !l.has("y_max"))
      l.fail("give at least one of x_min, x_max, y_min, y_max");
    if (limits.x_min >= limits.x_max) l.at("x_max").fail("must be greater than x_min");
    if (limits.y_min >= limits.y_max) l.at("y_max").fail("must be greater than y_min");
    return limits;
  }
  if (kind == "circle" || kind == "rectangle" || kind == "polygon") return read_region(f);
  f.at(kind).fail("unknown zone (expected circle, rectangle, polygon, ring or limits)");
}

RobotFilter read_robot_filter(const Field& parent, const char* key) {
  RobotFilter filter;
  if (!parent.has(key)) return filter;
  const Field f = parent.at(key);
  const std::string kind = f.single_key("in, not_in");
  if (kind == "in") {
    filter.kind = RobotFilter::Kind::InZone;
    filter.zones.push_back(read_zone(f.at("in")));
  } else if (kind == "not_in") {
    const Field list = f.at("not_in");
    if (list.items() == 0) list.fail("give at least one zone");
    filter.kind = RobotFilter::Kind::OutsideZones;
    for (std::size_t i = 0; i < list.items(); ++i) filter.zones.push_back(read_zone(list.at(i)));
  } else {
    f.at(kind).fail("unknown filter (expected in or not_in)");
  }
  return filter;
}

}  // namespace sd
