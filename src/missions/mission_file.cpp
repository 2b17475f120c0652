// Reading a mission file: JSON (comments allowed) checked field by field, so that a typo
// is reported with the path of the field and nothing runs.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>

#include "core/bounded_file.hpp"
#include "core/fnv.hpp"
#include "core/json_syntax.hpp"
#include "core/math.hpp"
#include "missions/json_field.hpp"
#include "missions/mission.hpp"
#include "missions/read_shapes.hpp"
#include "simulator/epuck.hpp"

namespace sd {

namespace {

using nlohmann::json;

Wall make_wall(Vec2 center, Vec2 axis, double length, double thickness, double height) {
  Wall w;
  w.center = center;
  w.axis = axis;
  w.half_length = 0.5 * length;
  w.half_thickness = 0.5 * thickness;
  w.height = height;
  return w;
}

void read_walls(const Field& f, Mission& m) {
  ArenaModel& arena = m.arena;
  for (std::size_t i = 0; i < f.array().size(); ++i) {
    const Field item = f.at(i);
    item.only({"box", "regular_polygon", "led_polygon"});
    if (item.raw().size() != 1) item.fail("expected exactly one of box, regular_polygon, led_polygon");
    if (item.has("led_polygon")) {
      // Events address LED blocks by side and block number: one LED arena per mission.
      if (!m.led_arena.empty()) item.at("led_polygon").fail("a mission has at most one led_polygon");
      m.led_arena = read_led_polygon(item.at("led_polygon"), arena);
    } else if (item.has("box")) {
      // ARGoS <box size="sx,sy,sz"> with a yaw: local x and y extents rotated by the yaw.
      const Field b = item.at("box");
      b.only({"center", "size", "yaw", "height", "placed_after_robots"});
      const Vec2 size = b.at("size").vec2();
      if (size.x <= 0 || size.y <= 0) b.at("size").fail("sizes must be positive");
      const double yaw = degrees_to_radians(b.number_or("yaw", 0.0));
      const double height = b.positive_or("height", 0.08);
      const Vec2 local_x = Vec2::polar(1.0, yaw), local_y = Vec2::polar(1.0, yaw + kPi / 2);
      arena.walls.push_back(size.y >= size.x ? make_wall(b.at("center").vec2(), local_y, size.y, size.x, height)
                                             : make_wall(b.at("center").vec2(), local_x, size.x, size.y, height));
      arena.walls.back().placed_after_robots = b.boolean_or("placed_after_robots", false);
    } else if (item.has("regular_polygon")) {
      // The AutoMoDe dodecagon and its kin: one box per side, tangent to the inscribed circle.
      // Side k (0-based) is centred at polar angle first_angle + 360 k / sides; `omit` leaves
      // sides out (the Coconut unbounded workspace opens the dodecagon's three top sides).
      const Field p = item.at("regular_polygon");
      p.only({"sides", "apothem", "length", "thickness", "height", "first_angle", "omit", "placed_after_robots"});
      const int sides = p.at("sides").integer_in(3, 64);
      const double apothem = p.at("apothem").positive();
      const double length = p.positive_or("length", 2.0 * apothem * math::tan(kPi / sides));
      const double thickness = p.positive_or("thickness", 0.01);
      const double height = p.positive_or("height", 0.08);
      const double first = degrees_to_radians(p.number_or("first_angle", 0.0));
      const bool after = p.boolean_or("placed_after_robots", false);
      std::vector<bool> omitted(static_cast<std::size_t>(sides), false);
      if (p.has("omit")) {
        const Field omit = p.at("omit");
        for (std::size_t j = 0; j < omit.items(); ++j) {
          const int k = omit.at(j).integer_in(0, sides - 1);
          if (omitted[static_cast<std::size_t>(k)]) omit.at(j).fail("side " + std::to_string(k) + " is omitted twice");
          omitted[static_cast<std::size_t>(k)] = true;
        }
      }
      for (int k = 0; k < sides; ++k) {
        if (omitted[static_cast<std::size_t>(k)]) continue;
        const double phi = first + kTwoPi * k / sides;
        arena.walls.push_back(make_wall(Vec2::polar(apothem, phi), Vec2::polar(1.0, phi + kPi / 2), length, thickness, height));
        arena.walls.back().placed_after_robots = after;
      }
    }
  }
}

void read_arena(const Field& f, Mission& m) {
  f.only({"walls", "floor", "lights"});
  if (f.has("walls")) read_walls(f.at("walls"), m);
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
  f.expect_object();
  for (const auto& item : f.raw().items()) {
    const std::string& key = item.key();
    const auto knob = std::find_if(kRobotKnobs.begin(), kRobotKnobs.end(), [&](const RobotKnob& k) { return k.name == key; });
    if (knob == kRobotKnobs.end()) f.at(key).fail("unknown field");
    const double v = f.at(key).number();
    const std::string_view error = knob_domain_error(knob->domain, v);
    if (!error.empty()) f.at(key).fail(std::string(error));
    r.*(knob->member) = v;
  }
}

/// {"loop_functions": {"label", "library", "params": {attribute: number, text or boolean}}}.
void read_argos(const Field& f, Mission& m) {
  f.only({"loop_functions"});
  if (!f.has("loop_functions")) return;
  const Field lf = f.at("loop_functions");
  lf.only({"label", "library", "params"});
  ArgosLoopFunctions loop;
  loop.label = lf.at("label").text();
  loop.library = lf.at("library").text();
  if (loop.label.empty()) lf.at("label").fail("must not be empty");
  if (loop.library.empty()) lf.at("library").fail("must not be empty");
  if (lf.has("params")) {
    const Field params = lf.at("params");
    params.expect_object();
    for (const auto& [key, value] : params.raw().items()) {
      if (key == "number_robots") params.at(key).fail("is written from the mission's robots");
      if (value.is_string()) loop.params.emplace_back(key, value.get<std::string>());
      else if (value.is_boolean()) loop.params.emplace_back(key, value.get<bool>() ? "true" : "false");
      else if (value.is_number()) loop.params.emplace_back(key, value.dump());
      else params.at(key).fail("expected a number, a text or a boolean");
    }
  }
  m.argos_loop_functions = std::move(loop);
}

/// The objective types a mission file may name, with their readers.
struct ObjectiveType {
  const char* name;
  std::function<ObjectiveParameters(const Field&)> read;
};
const ObjectiveType kObjectiveTypes[] = {
    {"robots_in_region_per_tick", read_region_count},
    {"best_region_fraction_at_end", read_best_region},
    {"foraging", read_foraging},
    {"grid_exploration", read_grid_exploration},
    {"mean_distance_to_robots", read_mean_distance},
    {"largest_network_coverage", read_network_coverage},
    {"stop_then_move", read_stop_then_move},
};

ObjectiveSpec read_objective(const Field& f) {
  ObjectiveSpec spec;
  spec.type = f.at("type").text();
  const std::string direction = f.at("direction").text();
  if (direction == "maximize") spec.direction = Direction::Maximize;
  else if (direction == "minimize") spec.direction = Direction::Minimize;
  else f.at("direction").fail("must be \"maximize\" or \"minimize\"");
  std::string known;
  for (const ObjectiveType& type : kObjectiveTypes) {
    if (spec.type == type.name) {
      spec.parameters = type.read(f);
      return spec;
    }
    known += (known.empty() ? "" : ", ") + std::string(type.name);
  }
  f.at("type").fail("unknown objective type '" + spec.type + "' (known: " + known + ")");
}

void read_events(const Field& f, Mission& m) {
  for (std::size_t i = 0; i < f.items(); ++i) {
    MissionEvent event = read_mission_event(f.at(i), m.led_arena, m.ticks);
    for (const MissionEvent& other : m.events)
      if (other.name == event.name) f.at(i).at("name").fail("another event is named '" + event.name + "'");
    m.events.push_back(std::move(event));
  }
}

/// Objectives that refer to a mission event name it; find its index once, here.
void resolve_event_names(const Field& f, Mission& m) {
  auto* stop = std::get_if<StopThenMoveObjective>(&m.objective.parameters);
  if (!stop) return;
  for (std::size_t e = 0; e < m.events.size(); ++e)
    if (m.events[e].name == stop->switch_event) {
      stop->event = e;
      return;
    }
  f.at("switch_event").fail("no event is named '" + stop->switch_event + "'");
}

/// The box that holds every wall, if there are walls.
std::optional<std::pair<Vec2, Vec2>> walls_bounds(const ArenaModel& arena) {
  if (arena.walls.empty()) return std::nullopt;
  constexpr double kHuge = 1e300;
  Vec2 lo{kHuge, kHuge}, hi{-kHuge, -kHuge};
  for (const Wall& w : arena.walls) {
    // Corners of the wall's rectangle.
    for (const double a : {-1.0, 1.0})
      for (const double b : {-1.0, 1.0}) {
        const Vec2 c = w.center + w.axis * (a * w.half_length) + w.normal() * (b * w.half_thickness);
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
      }
  }
  return std::make_pair(lo, hi);
}

std::string bounds_text(const std::pair<Vec2, Vec2>& b) {
  std::ostringstream out;
  out << "x in [" << b.first.x << ", " << b.second.x << "], y in [" << b.first.y << ", " << b.second.y << "]";
  return out.str();
}

/// Walls and floor patches within 10 m of the origin: an e-puck arena is a few metres across,
/// and the compiled arena has cells of 2 cm over the walls' and patches' box, so a wall 12 km
/// out (a typo, or a file made to hurt) would ask for terabytes. Found by fuzz_mission.
constexpr double kArenaReach = 10.0;

bool within_reach(const std::pair<Vec2, Vec2>& b) {
  return b.first.x >= -kArenaReach && b.first.y >= -kArenaReach && b.second.x <= kArenaReach && b.second.y <= kArenaReach;
}

void check_arena_extent(const Field& root, const Mission& m) {
  if (const auto walls = walls_bounds(m.arena); walls && !within_reach(*walls))
    root.at("arena").at("walls").fail("reach beyond 10 m from the origin (they span " + bounds_text(*walls) +
                                      "); an e-puck arena is a few metres across");
  for (std::size_t i = 0; i < m.arena.floor_patches.size(); ++i) {
    const auto bounds = m.arena.floor_patches[i].region.bounds();
    if (!within_reach(bounds))
      root.at("arena").at("floor").at("patches").at(i).fail("reaches beyond 10 m from the origin (" + bounds_text(bounds) + ")");
  }
}

/// A floor patch nobody can drive on is a mistake in the file (a sign or a unit wrong).
void check_patches_touch_arena(const Field& root, const Mission& m) {
  const auto walls = walls_bounds(m.arena);
  if (!walls) return;
  for (std::size_t i = 0; i < m.arena.floor_patches.size(); ++i) {
    const auto [lo, hi] = m.arena.floor_patches[i].region.bounds();
    if (hi.x < walls->first.x || lo.x > walls->second.x || hi.y < walls->first.y || lo.y > walls->second.y)
      root.at("arena").at("floor").at("patches").at(i).fail("lies outside the arena (the walls span " + bounds_text(*walls) + ")");
  }
}

/// Robots must start within the walls; placement only keeps them off the walls themselves.
void check_start_inside_walls(const Field& root, const Mission& m) {
  const auto walls = walls_bounds(m.arena);
  if (!walls) return;
  const auto [lo, hi] = m.start.bounds();
  if (lo.x < walls->first.x || hi.x > walls->second.x || lo.y < walls->first.y || hi.y > walls->second.y)
    root.at("start").fail("reaches outside the walls (they span " + bounds_text(*walls) + ")");
}

/// A robot's centre needs this much free space: fail early instead of after 1000 trials.
void check_swarm_fits(const Field& root, const Mission& m) {
  const double body_area = kPi * epuck::kBodyRadius * epuck::kBodyRadius;
  // Random sequential packing of discs jams near 55 % coverage; stay well below.
  if (m.robots * body_area > 0.4 * m.start.area())
    root.at("robots").fail(std::to_string(m.robots) + " robots do not fit in the start region");
}

/// The digest of the document without the fields that only describe it (and "argos", which
/// only the ARGoS export reads); keys come out
/// sorted and without spaces, so layout and comments do not count either.
std::string runs_digest(json document, const arlequin::ModuleSet* arlequin_modules) {
  for (const char* descriptive : {"title", "origin", "description", "argos"}) document.erase(descriptive);
  Fnv1a f;
  f.add(document.dump());
  if (arlequin_modules) f.add(arlequin_modules->digest);  // a folder's files may change
  return f.hex();
}

/// "swarmdesign", "demiurge", or a folder: relative to the mission file's folder when the
/// mission was read from a file, else to the current folder.
std::shared_ptr<const arlequin::ModuleSet> read_arlequin_modules(const Field& f, const std::string& source, const PathRule& allowed) {
  std::string name = f.text();
  if (!arlequin::builtin_module_set(name) && std::filesystem::path(name).is_relative()) {
    const std::filesystem::path file(source);
    if (file.has_parent_path() && std::filesystem::is_regular_file(file)) name = (file.parent_path() / name).string();
  }
  try {
    return arlequin::load_module_set(name, allowed);
  } catch (const std::runtime_error& e) {
    f.fail(e.what());
  }
}

}  // namespace

std::string_view direction_name(Direction d) { return d == Direction::Maximize ? "maximize" : "minimize"; }

Mission parse_mission(const std::string& json_text, const std::string& source, const PathRule& allowed) {
  json document;
  try {
    document = json::parse(json_text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw MissionError("not valid JSON: " + json_syntax_error(e, json_text));
  } catch (const json::out_of_range& e) {
    throw MissionError("not valid JSON: " + json_number_error(e));
  }
  const Field root(document, "");
  root.only({"name", "title", "origin", "description", "duration", "robots", "arena", "start", "robot", "arrest", "events", "objective", "argos",
             "arlequin_modules"});
  Mission m;
  m.source = source;
  if (root.has("arlequin_modules")) m.arlequin_modules = read_arlequin_modules(root.at("arlequin_modules"), source, allowed);
  m.digest = runs_digest(document, m.arlequin_modules.get());
  m.document = json_text;
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
  if (const auto arc = read_jittered_arc(root.at("start"))) {
    m.start_arc = arc;
    m.start = arc->support();
  } else {
    m.start = read_region(root.at("start"));
  }
  if (root.has("robot")) read_robot_model(root.at("robot"), m.robot);
  if (root.has("arrest")) m.arrest = read_arrest_rule(root.at("arrest"));
  if (root.has("events")) read_events(root.at("events"), m);
  m.objective = read_objective(root.at("objective"));
  if (root.has("argos")) read_argos(root.at("argos"), m);
  resolve_event_names(root.at("objective"), m);
  check_arena_extent(root, m);
  check_patches_touch_arena(root, m);
  check_start_inside_walls(root, m);
  check_swarm_fits(root, m);
  m.arena.compile();
  return m;
}

Mission with_arlequin_modules(const Mission& mission, const std::string& name_or_folder, const PathRule& allowed) {
  json document = json::parse(mission.document, nullptr, true, /*ignore_comments=*/true);
  // A folder by absolute path, so the document reads the same set from anywhere; anything
  // else as given, for parse_mission to accept or name in its error.
  std::error_code ec;
  const bool folder = !arlequin::builtin_module_set(name_or_folder) && std::filesystem::is_directory(name_or_folder, ec);
  document["arlequin_modules"] =
      folder ? std::filesystem::absolute(name_or_folder).lexically_normal().string() : name_or_folder;
  return parse_mission(document.dump(1), mission.source, allowed);
}

Mission load_mission_file(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_bounded_file(path, "mission file").text;
  } catch (const FileReadError& e) {
    throw MissionError(e.what());
  }
  try {
    return parse_mission(text, path.string());
  } catch (const MissionError& e) {
    throw MissionError(path.filename().string() + ": " + e.what());
  }
}

}  // namespace sd
