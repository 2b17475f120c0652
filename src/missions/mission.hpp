#pragma once
// A mission: the arena, the swarm, where it starts, how long it runs and how it is scored.
// Missions are data (JSON files in missions/ or anywhere a user puts them); loading one
// validates every field and compiles the arena once, so evaluations only read it.
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/bounded_file.hpp"
#include "missions/arrest_rule.hpp"
#include "missions/led_arena.hpp"
#include "missions/mission_events.hpp"
#include "missions/objective_best_region.hpp"
#include "missions/objective_foraging.hpp"
#include "missions/objective_grid_exploration.hpp"
#include "missions/objective_mean_distance.hpp"
#include "missions/objective_network_coverage.hpp"
#include "missions/objective_region_count.hpp"
#include "missions/objective_stop_then_move.hpp"
#include "missions/start_distribution.hpp"
#include "modules/arlequin_module_set.hpp"
#include "simulator/arena.hpp"
#include "simulator/region.hpp"
#include "simulator/robot_model.hpp"

namespace sd {

enum class Direction { Maximize, Minimize };

/// The ARGoS3 loop functions that score the mission in the AutoMoDe tool chain (mission file
/// field "argos"): the label their REGISTER_LOOP_FUNCTIONS gives, the library's path inside
/// the experiments-loop-functions build folder, and attributes their <params> read beyond
/// number_robots. Only the ARGoS export reads it; runs do not depend on it.
struct ArgosLoopFunctions {
  std::string label;
  std::string library;
  std::vector<std::pair<std::string, std::string>> params;  // attribute, value as written
};
std::string_view direction_name(Direction d);

/// The objective types, each a reusable building block (objective_<idea>.hpp) whose
/// parameters name their per-run score type. The file names them by `type`
/// (mission_file.cpp holds the table).
using ObjectiveParameters = std::variant<RegionCountObjective, BestRegionObjective, ForagingObjective,
                                         GridExplorationObjective, MeanDistanceObjective, NetworkCoverageObjective,
                                         StopThenMoveObjective>;

struct ObjectiveSpec {
  std::string type;
  Direction direction = Direction::Maximize;
  ObjectiveParameters parameters;
};

struct StartPose {
  Vec2 position;
  double yaw = 0.0;  // rad
};

struct Mission {
  std::string name;
  std::string title;
  std::string origin;          // the AutoMoDe flavour that introduced it
  std::string description;
  std::string source;          // file it was read from, or "built-in"
  /// Digest of what the runs depend on: the document less its title, origin and
  /// description. A design records it, so that a resumed design can tell that its mission
  /// file has been edited in the meantime.
  std::string digest;
  /// The document's text as read: what another process (an MPI rank) rebuilds the mission from.
  std::string document;
  double duration_s = 120.0;
  int ticks = 1200;
  int robots = 20;
  Region start;                         // where robots start (for start_arc: the square it fills)
  std::optional<JitteredArc> start_arc;  // TuttiFrutti's own start draw
  ArenaModel arena;
  LedArena led_arena;                   // which arena LEDs make which block (TuttiFrutti)
  RobotModel robot;
  std::optional<ArrestRule> arrest;     // Coconut unbounded workspace
  std::vector<MissionEvent> events;     // TuttiFrutti LED colours
  ObjectiveSpec objective;
  std::optional<ArgosLoopFunctions> argos_loop_functions;
  /// Field "arlequin_modules": the module set that runs Arlequin's modules 50-55
  /// ("swarmdesign", "demiurge" or a folder); null when the field is absent, which runs the
  /// shipped networks exactly as "swarmdesign" does. The digest covers a folder's weights.
  std::shared_ptr<const arlequin::ModuleSet> arlequin_modules;
  /// When not empty, every run starts from these poses, one per robot, instead of drawing
  /// them (evaluate --start-from: ARGoS' own tick-0 poses, so that a comparison with ARGoS is
  /// not also a comparison of two start samples). The draw still happens, so the seed's noise
  /// streams are those of an ordinary run. Never part of a mission file or a design.
  std::vector<StartPose> start_poses;

  /// One start position, as placement draws it (before rejecting overlaps).
  Vec2 draw_start(Rng& rng) const;
};

/// Invalid mission file: the message names the field ("arena.floor.patches[1].radius: ...").
struct MissionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// `allowed`: where files the mission names (an Arlequin module-set folder) may be read; anywhere if empty.
Mission parse_mission(const std::string& json_text, const std::string& source, const PathRule& allowed = {});
Mission load_mission_file(const std::filesystem::path& path);
/// The mission with its "arlequin_modules" field set to `name_or_folder` (a folder made
/// absolute from the current one), re-read so that its document and digest say so (what a
/// design records and an MPI rank rebuilds). MissionError naming the field if the set is bad.
Mission with_arlequin_modules(const Mission& mission, const std::string& name_or_folder, const PathRule& allowed = {});

}  // namespace sd
