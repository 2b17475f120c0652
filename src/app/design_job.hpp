#pragma once
// One design process as a job: mission + design space + budget + seed, raced by Iterated
// F-Race on an Evaluator, checkpointed into DIR/design.db after every race step, watched by an
// observer, cancelled between two steps, resumed after a cancel or a kill -9 to exactly the
// result of an uninterrupted run. The CLI's `design` and `run-design`, a web server and an MPI
// rank all run designs through here.
//
//   PreparedDesign d = prepare_new_design(settings, folder);   // or prepare_resume(folder)
//   DesignOutcome o = run_design(d, {.threads = 2, .observer = &observer, .cancel = &token});
//
// prepare_* check everything (mission, flags, minimum budget, the folder) without side
// effects, so a caller can refuse bad input before it records or forks anything.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cancel_token.hpp"
#include "app/pseudo_realities.hpp"
#include "app/user_files.hpp"
#include "control/control_software.hpp"
#include "design/design_space.hpp"
#include "design/iterated_race.hpp"
#include "design/methods.hpp"
#include "evaluation/evaluator.hpp"
#include "missions/mission.hpp"

namespace sd::app {

/// The samples a robust design races on by default: not assess's default 1-20, so that an
/// assessment after the design is on pseudo-realities it never saw.
inline constexpr std::string_view kDefaultDesignSamples = "101-120";

struct NewDesignSettings {
  std::string mission;  // name or mission file
  long long budget = 0;
  design::DesignSpaceRequest space;
  std::uint64_t seed = 0;
  FileScope files = FileScope::local();  // where the mission file may be (a server: the user's projects)
  /// A robust design (Ligot & Birattari 2020, one step further): a pseudo-reality specification
  /// (shipped name or file) whose samples are the race's instances, each drawn with its own
  /// seeds, so the race keeps control software that holds across robot models. Empty: the
  /// design model alone.
  std::string pseudo_reality{};
  std::string pseudo_reality_samples = std::string(kDefaultDesignSamples);
  std::string pseudo_reality_document{};  // its text when already read (a design resumed); else loaded
  /// The optimiser over the space (design/methods.hpp: automode, random-search, local-search).
  const design::MethodInfo* method = &design::kAutoMoDe;
};

struct PreparedDesign {
  std::filesystem::path folder;
  Mission mission;
  std::string mission_reference;  // as stored: catalogue name or absolute path
  design::DesignSpaceChoice choice;
  const design::MethodInfo* method = &design::kAutoMoDe;
  std::unique_ptr<design::ParameterSpace> space;  // IteratedRace keeps a reference to it
  design::IraceOptions options;
  std::optional<design::DesignState> restored;    // set when resuming from a checkpoint
  bool resuming = false;
  /// A robust design's pseudo-realities: instance i runs in instance_models[i].
  std::optional<NamedPseudoReality> reality;
  std::string reality_samples;  // "A-B"
  std::vector<RobotModel> instance_models;
};

/// Checks the settings of a new design (no folder yet): InvalidRequest for an unknown
/// mission, an unavailable flavour or a budget below the engine's minimum.
PreparedDesign check_new_design(const NewDesignSettings& settings);
/// check_new_design in a folder; DesignFolderError when it already holds a design.
/// An empty folder means ./design-<mission>-seed<S> (with -2, -3 ... when taken).
PreparedDesign prepare_new_design(const NewDesignSettings& settings, const std::filesystem::path& folder);
/// The design in `folder` as asked, the rule every front end follows (`design --out DIR`,
/// Python's design(folder=...)): a new one when the folder holds none; else the one it holds,
/// resumed (or, finished, read back: run_design then only reports it) when it was started with
/// these settings (mission, budget, seed, design space, pseudo-realities and their samples);
/// else DesignFolderError naming the settings it was started with.
PreparedDesign prepare_design_in(const NewDesignSettings& settings, const std::filesystem::path& folder);
/// Whether a prepared design has nothing left to run (a finished one read back).
bool already_finished(const PreparedDesign& d);
/// DesignFolderError for a folder that is not a design, of another format or space, damaged,
/// whose mission changed or whose runs this build would score differently, or (unless
/// allow_finished) finished.
PreparedDesign prepare_resume(const std::filesystem::path& folder, bool allow_finished = false,
                              const FileScope& files = FileScope::local());

struct EliteReport {
  int id = 0;
  std::string configuration;
  double mean_score = 0.0;       // the mission's natural units
  std::size_t evaluations = 0;
};

struct DesignReport {
  std::filesystem::path folder;
  std::string mission, direction;
  std::string method;  // design/methods.hpp
  long long budget = 0;
  std::uint64_t seed = 0;
  std::string architectures, flavours;
  std::vector<std::string> notes;
  std::string pseudo_reality{}, pseudo_reality_samples{};  // a robust design's; empty otherwise
  bool resumed = false;
  long long experiments_used = 0;
  int iterations = 0;
  std::string finish_reason;
  ControlSoftware best;
  std::vector<EliteReport> elites;  // best first
  double wall_seconds = 0.0, evaluation_seconds = 0.0;
  int threads = 0;
};

/// What a running design tells whoever watches it. Called on the job's thread.
class DesignObserver {
 public:
  virtual ~DesignObserver() = default;
  /// After every race step (scores are costs: negate for a maximised mission, or use
  /// `best_score` of the progress document).
  virtual void progress(const design::Progress&) {}
  /// After checkpoint `step` is durably in design.db: a kill from now on resumes from here.
  virtual void checkpoint(std::int64_t /*step*/) {}
};

struct DesignRunOptions {
  unsigned threads = 0;               // local threads when no evaluator is given (0: all cores)
  Evaluator* evaluator = nullptr;     // another backend (MPI ranks, ...); else threads
  DesignObserver* observer = nullptr;
  const CancelToken* cancel = nullptr;  // the design stops between two runs, the step it was in dropped: it resumes from the last durable one
};

struct DesignOutcome {
  bool cancelled = false;             // stopped by the token: resumable with prepare_resume
  std::optional<DesignReport> report; // set when the design finished
  long long experiments_used = 0;
};

DesignOutcome run_design(PreparedDesign& design, const DesignRunOptions& options);

/// The smallest budget the engine accepts for this space (irace's minimum). nb_iterations 0
/// means the default floor(2 + log2 N_param), as both the engine and irace pick it.
long long minimum_design_budget(const design::ParameterSpace& space, int nb_iterations = 0);
/// The smallest budget `method` accepts for this space.
long long minimum_design_budget(const design::MethodInfo& method, const design::ParameterSpace& space);
/// InvalidRequest naming the minimum when `budget` is below it: `design`, `run-design` and
/// `irace-export` refuse a too small budget with the same words.
void require_minimum_budget(long long budget, const design::ParameterSpace& space, int nb_iterations = 0);
/// The design method of that name with a modular design space (automode, random-search,
/// local-search); InvalidRequest naming them for any other.
const design::MethodInfo& search_method(std::string_view name);
/// "automode, random-search or local-search", for help texts.
std::string search_method_names();
/// The design space of the flags; InvalidRequest for a flavour without modules.
design::DesignSpaceChoice resolve_space(const design::DesignSpaceRequest& request);

}  // namespace sd::app
