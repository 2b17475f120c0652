// Reading a mission file: JSON (comments allowed) checked field by field, so that a typo
// is reported with the path of the field and nothing runs.
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "missions/mission.hpp"
#include "simulator/epuck.hpp"

namespace sd {

namespace {

using nlohmann::json;

/// A JSON value together with its path in the file, for error messages.
class Field {
 public:
  Field(const json& value, std::string path) : value_(value), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const { throw MissionError(path_ + ": " + what); }

  const std::string& path() const { return path_; }
  const json& raw() const { return value_; }

  Field at(const std::string& key) const {
    expect_object();
    if (!value_.contains(key)) throw MissionError(child_path(key) + ": missing field");
    return Field(value_.at(key), child_path(key));
  }
  bool has(const std::string& key) const { return value_.is_object() && value_.contains(key); }
  Field at(std::size_t index) const { return Field(value_.at(index), path_ + "[" + std::to_string(index) + "]"); }
  std::size_t size() const { return value_.size(); }

  /// Rejects keys this reader does not know: a misspelt field must not be ignored.
  void only(std::initializer_list<const char*> keys) const {
    expect_object();
    const std::set<std::string> allowed(keys.begin(), keys.end());
    for (const auto& [key, v] : value_.items())
      if (!allowed.count(key)) throw MissionError(child_path(key) + ": unknown field");
  }

  void expect_object() const {
    if (!value_.is_object()) fail("expected an object");
  }
  const json& array() const {
    if (!value_.is_array()) fail("expected a list");
    return value_;
  }
  double number() const {
    if (!value_.is_number()) fail("expected a number");
    const double v = value_.get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    return v;
  }
  double positive() const {
    const double v = number();
    if (v <= 0.0) fail("must be positive");
    return v;
  }
  double non_negative() const {
    const double v = number();
    if (v < 0.0) fail("must not be negative");
    return v;
  }
  double probability() const {
    const double v = number();
    if (v < 0.0 || v > 1.0) fail("must be in [0, 1]");
    return v;
  }
  int integer() const {
    if (!value_.is_number_integer()) fail("expected an integer");
    return value_.get<int>();
  }
  bool boolean() const {
    if (!value_.is_boolean()) fail("expected true or false");
    return value_.get<bool>();
  }
  std::string text() const {
    if (!value_.is_string()) fail("expected a string");
    return value_.get<std::string>();
  }
  Vec2 vec2() const {
    if (!value_.is_array() || value_.size() != 2) fail("expected [x, y]");
    return {at(0).number(), at(1).number()};
  }
  Vec3 vec3() const {
    if (!value_.is_array() || value_.size() != 3) fail("expected [x, y, z]");
    return {at(0).number(), at(1).number(), at(2).number()};
  }

 private:
  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const json& value_;
  std::string path_;
};

struct NamedColor {
  const char* name;
  std::uint32_t rgb;
};
// ARGoS' named colours; gray is GRAY50.
constexpr NamedColor kColors[] = {{"black", 0x000000}, {"white", 0xffffff}, {"gray", 0x7f7f7f},
                                  {"red", 0xff0000},   {"green", 0x00ff00}, {"blue", 0x0000ff},
                                  {"yellow", 0xffff00}, {"magenta", 0xff00ff}, {"cyan", 0x00ffff}};

std::uint32_t read_color(const Field& f) {
  const std::string name = f.text();
  for (const auto& c : kColors)
    if (name == c.name) return c.rgb;
  if (name.size() == 7 && name[0] == '#') {
    try {
      return static_cast<std::uint32_t>(std::stoul(name.substr(1), nullptr, 16));
    } catch (...) {
    }
  }
  f.fail("unknown colour '" + name + "' (black, white, gray, red, green, blue, yellow, magenta, cyan or #rrggbb)");
}

double gray_of(std::uint32_t rgb) {
  // Ground sensor: 0.299 R + 0.587 G + 0.114 B, over 255 (ARGoS ToGrayScale).
  const double r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
  return (0.299 * r + 0.587 * g + 0.114 * b) / 255.0;
}

Region read_region(const Field& f) {
  f.expect_object();
  if (f.raw().size() != 1) f.fail("expected exactly one of circle, rectangle, polygon");
  if (f.has("circle")) {
    const Field c = f.at("circle");
    c.only({"center", "radius", "inclusive"});
    const bool inclusive = c.has("inclusive") ? c.at("inclusive").boolean() : true;
    return Region::circle(c.at("center").vec2(), c.at("radius").positive(), inclusive);
  }
  if (f.has("rectangle")) {
    const Field r = f.at("rectangle");
    r.only({"center", "size", "yaw"});
    const Vec2 size = r.at("size").vec2();
    if (size.x <= 0 || size.y <= 0) r.at("size").fail("sizes must be positive");
    return Region::rectangle(r.at("center").vec2(), size, r.has("yaw") ? degrees_to_radians(r.at("yaw").number()) : 0.0);
  }
  if (f.has("polygon")) {
    const Field p = f.at("polygon");
    std::vector<Vec2> vertices;
    for (std::size_t i = 0; i < p.array().size(); ++i) vertices.push_back(p.at(i).vec2());
    if (vertices.size() < 3) p.fail("a polygon needs at least 3 vertices");
    Region region = Region::polygon(std::move(vertices));
    if (region.area() <= 0.0) p.fail("the polygon has no area");
    return region;
  }
  f.fail("expected one of circle, rectangle, polygon");
}

Wall make_wall(Vec2 center, Vec2 axis, double length, double thickness, double height) {
  Wall w;
  w.center = center;
  w.axis = axis;
  w.half_length = 0.5 * length;
  w.half_thickness = 0.5 * thickness;
  w.height = height;
  return w;
}

void read_walls(const Field& f, ArenaModel& arena) {
  for (std::size_t i = 0; i < f.array().size(); ++i) {
    const Field item = f.at(i);
    item.expect_object();
    if (item.has("box")) {
      // ARGoS <box size="sx,sy,sz"> with a yaw: local x and y extents rotated by the yaw.
      const Field b = item.at("box");
      b.only({"center", "size", "yaw", "height"});
      const Vec2 size = b.at("size").vec2();
      if (size.x <= 0 || size.y <= 0) b.at("size").fail("sizes must be positive");
      const double yaw = b.has("yaw") ? degrees_to_radians(b.at("yaw").number()) : 0.0;
      const double height = b.has("height") ? b.at("height").positive() : 0.08;
      const Vec2 local_x = Vec2::polar(1.0, yaw), local_y = Vec2::polar(1.0, yaw + kPi / 2);
      arena.walls.push_back(size.y >= size.x ? make_wall(b.at("center").vec2(), local_y, size.y, size.x, height)
                                             : make_wall(b.at("center").vec2(), local_x, size.x, size.y, height));
    } else if (item.has("regular_polygon")) {
      // The AutoMoDe dodecagon and its kin: one box per side, tangent to the inscribed circle.
      const Field p = item.at("regular_polygon");
      p.only({"sides", "apothem", "length", "thickness", "height", "first_angle"});
      const int sides = p.at("sides").integer();
      if (sides < 3 || sides > 64) p.at("sides").fail("must be between 3 and 64");
      const double apothem = p.at("apothem").positive();
      const double length = p.has("length") ? p.at("length").positive() : 2.0 * apothem * std::tan(kPi / sides);
      const double thickness = p.has("thickness") ? p.at("thickness").positive() : 0.01;
      const double height = p.has("height") ? p.at("height").positive() : 0.08;
      const double first = p.has("first_angle") ? degrees_to_radians(p.at("first_angle").number()) : 0.0;
      for (int k = 0; k < sides; ++k) {
        const double phi = first + kTwoPi * k / sides;
        arena.walls.push_back(make_wall(Vec2::polar(apothem, phi), Vec2::polar(1.0, phi + kPi / 2), length, thickness, height));
      }
    } else {
      item.fail("expected {\"box\": ...} or {\"regular_polygon\": ...}");
    }
  }
}

void read_arena(const Field& f, Mission& m) {
  f.only({"walls", "floor", "lights"});
  if (f.has("walls")) read_walls(f.at("walls"), m.arena);
  if (f.has("floor")) {
    const Field floor = f.at("floor");
    floor.only({"background", "patches"});
    if (floor.has("background")) {
      m.arena.floor_background_rgb = read_color(floor.at("background"));
      m.arena.floor_background_gray = gray_of(m.arena.floor_background_rgb);
    }
    if (floor.has("patches")) {
      const Field patches = floor.at("patches");
      for (std::size_t i = 0; i < patches.array().size(); ++i) {
        const Field p = patches.at(i);
        p.only({"region", "color"});
        FloorPatch patch;
        patch.region = read_region(p.at("region"));
        patch.rgb = read_color(p.at("color"));
        patch.gray = gray_of(patch.rgb);
        m.arena.floor_patches.push_back(std::move(patch));
      }
    }
  }
  if (f.has("lights")) {
    const Field lights = f.at("lights");
    for (std::size_t i = 0; i < lights.array().size(); ++i) {
      const Field l = lights.at(i);
      l.only({"position", "intensity", "color"});
      Light light;
      light.position = l.at("position").vec3();
      light.intensity = l.at("intensity").non_negative();
      if (l.has("color")) light.rgb = read_color(l.at("color"));
      m.arena.lights.push_back(light);
    }
  }
}

void read_robot_model(const Field& f, RobotModel& r) {
  f.only({"rab_range", "rab_loss", "wheel_noise", "proximity_noise", "light_noise", "ground_noise", "camera_range"});
  if (f.has("rab_range")) r.rab_range = f.at("rab_range").positive();
  if (f.has("rab_loss")) r.rab_loss = f.at("rab_loss").probability();
  if (f.has("wheel_noise")) r.wheel_noise = f.at("wheel_noise").non_negative();
  if (f.has("proximity_noise")) r.proximity_noise = f.at("proximity_noise").non_negative();
  if (f.has("light_noise")) r.light_noise = f.at("light_noise").non_negative();
  if (f.has("ground_noise")) r.ground_noise = f.at("ground_noise").non_negative();
  if (f.has("camera_range")) r.camera_range = f.at("camera_range").positive();
}

ObjectiveSpec read_objective(const Field& f) {
  ObjectiveSpec spec;
  spec.type = f.at("type").text();
  const std::string direction = f.at("direction").text();
  if (direction == "maximize") spec.direction = Direction::Maximize;
  else if (direction == "minimize") spec.direction = Direction::Minimize;
  else f.at("direction").fail("must be \"maximize\" or \"minimize\"");
  if (spec.type == "robots_in_region_per_tick") {
    f.only({"type", "direction", "region"});
    spec.parameters = objectives::RobotsInRegionPerTick{read_region(f.at("region"))};
  } else {
    f.at("type").fail("unknown objective type '" + spec.type + "' (known: robots_in_region_per_tick)");
  }
  return spec;
}

/// A robot's centre needs this much free space: fail early instead of after 1000 trials.
void check_swarm_fits(const Field& root, const Mission& m) {
  const double body_area = kPi * epuck::kBodyRadius * epuck::kBodyRadius;
  // Random sequential packing of discs jams near 55 % coverage; stay well below.
  if (m.robots * body_area > 0.4 * m.start.area())
    root.at("robots").fail(std::to_string(m.robots) + " robots do not fit in the start region");
}

}  // namespace

std::string_view direction_name(Direction d) { return d == Direction::Maximize ? "maximize" : "minimize"; }

Mission parse_mission(const std::string& json_text, const std::string& source) {
  json document;
  try {
    document = json::parse(json_text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw MissionError(std::string("not valid JSON: ") + e.what());
  }
  const Field root(document, "");
  root.only({"name", "title", "origin", "description", "duration", "robots", "arena", "start", "robot", "objective"});
  Mission m;
  m.source = source;
  m.name = root.at("name").text();
  if (m.name.empty() || m.name.find_first_of("/ \t") != std::string::npos)
    root.at("name").fail("must be a non-empty word without spaces or slashes");
  m.title = root.has("title") ? root.at("title").text() : m.name;
  m.origin = root.has("origin") ? root.at("origin").text() : "user";
  m.description = root.has("description") ? root.at("description").text() : "";
  m.duration_s = root.at("duration").positive();
  m.ticks = static_cast<int>(std::lround(m.duration_s / epuck::kTickSeconds));
  if (m.ticks < 1 || m.ticks > 10'000'000) root.at("duration").fail("must be between 0.1 s and 10^6 s");
  m.robots = root.at("robots").integer();
  if (m.robots < 1 || m.robots > 1000) root.at("robots").fail("must be between 1 and 1000");
  read_arena(root.at("arena"), m);
  m.start = read_region(root.at("start"));
  if (root.has("robot")) read_robot_model(root.at("robot"), m.robot);
  m.objective = read_objective(root.at("objective"));
  check_swarm_fits(root, m);
  m.arena.compile();
  return m;
}

Mission load_mission_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw MissionError("cannot read mission file " + path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    return parse_mission(buffer.str(), path.string());
  } catch (const MissionError& e) {
    throw MissionError(path.filename().string() + ": " + e.what());
  }
}

}  // namespace sd
