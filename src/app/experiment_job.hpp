#pragma once
// An experiment as a job: a protocol (experiments/protocol.hpp) becomes designs —
// one per mission, condition and replicate — that run one after the other through the design
// job (design_job.hpp) or EvoStick (evolution_job.hpp), each then assessed on fresh seeds.
// Everything is recorded in the project's database as it becomes durable, so a killed
// experiment, started again, resumes inside the design it was in and ends with exactly the
// results of an uninterrupted one.
//
//   PlannedExperiment plan = plan_experiment(protocol);          // every refusal, no side effect
//   StartedExperiment e = start_experiment(home, user, plan, {.owner = ...});
//   run_experiment(e, {.threads = 2, .observer = &display});

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/design_job.hpp"
#include "app/documents/experiments.hpp"
#include "app/home.hpp"
#include "app/user_files.hpp"
#include "experiments/protocol.hpp"
#include "storage/design_status.hpp"
#include "storage/experiments.hpp"
#include "storage/projects.hpp"

namespace sd::app {

/// The designs a protocol asks for, with their budgets and seeds, checked.
struct PlannedExperiment {
  experiments::Protocol protocol;
  std::vector<storage::PlannedDesign> designs;  // in the order they run
  std::vector<std::string> notes;               // e.g. budgets raised to the optimiser's minimum
  std::int64_t design_runs = 0;                 // simulation runs of all designs
  std::int64_t assessment_runs = 0;             // and of all assessments (pseudo-realities included)
};

/// InvalidRequest (naming the mission and condition) for a mission no catalogue has, a
/// flavour without modules; a scaled budget below the optimiser's minimum is raised to it,
/// with a note. A pseudo-reality the protocol names is read (through `scope`: a server's user
/// reads only their own projects' files) and its specification written into the plan's
/// protocol (`pseudo_reality.definition`), unless the protocol already holds one: the
/// experiment then resumes with the robot models it started with. InvalidRequest naming
/// `pseudo_reality.spec` for a bad one.
PlannedExperiment plan_experiment(const experiments::Protocol& protocol, const FileScope& scope = FileScope::local());

/// How a mission is named in displays and reports: a catalogue name as is, a mission file by
/// its file name without extension.
std::string mission_label(const std::string& reference);

/// The seeds every final design is assessed on: the same for every design (common random
/// numbers make conditions comparable), far from the seeds the races draw.
std::vector<std::uint64_t> assessment_seeds(int count);

/// How long the plan would take on this machine: each mission's simulation speed measured now
/// (a few runs of control software sampled from each condition's space), times its runs.
struct DurationEstimate {
  struct PerMission {
    std::string mission;
    std::int64_t runs = 0;
    double seconds_per_run = 0.0;  // wall time per run with all the threads
  };
  std::vector<PerMission> missions;
  double seconds = 0.0;
  int threads = 0;
};
DurationEstimate estimate_duration(const PlannedExperiment& plan, unsigned threads);

struct ExperimentStartRequest {
  std::optional<std::string> project;  // a project by name; nullopt: the active one
  std::string owner;                   // storage::Owner::text() of the job that runs it
};

struct StartedExperiment {
  std::filesystem::path home;
  storage::Project project;
  storage::Experiment experiment;
  bool resumed = false;                // it existed: it goes on where it stopped
  bool already_finished = false;
};

/// Records the experiment and its designs, or takes over an interrupted one of the same name
/// and protocol. Conflict when it runs elsewhere or its name is taken by another protocol.
StartedExperiment start_experiment(Home& home, const storage::User& user, const PlannedExperiment& plan,
                                   const ExperimentStartRequest& request);

/// What a running experiment tells whoever watches it (on the job's thread).
class ExperimentObserver {
 public:
  virtual ~ExperimentObserver() = default;
  /// A design starts or resumes (`index` of `total`, 1-based).
  virtual void design_started(const storage::ExperimentDesign&, int /*index*/, int /*total*/) {}
  /// The design is the same as one another experiment made: its result is taken.
  virtual void design_reused(const storage::ExperimentDesign& /*twin*/, const std::string& /*experiment*/) {}
  /// Inside a design: runs used of its budget, and its best estimated score so far.
  virtual void design_progress(std::int64_t /*runs_used*/, std::int64_t /*budget*/, double /*best_score*/) {}
  /// After a race step or generation is durable (where fault injection kills).
  virtual void checkpoint(std::int64_t /*step*/) {}
  virtual void assessing(std::size_t /*done*/, std::size_t /*all*/) {}
  /// The design is assessed: its mean score on the assessment seeds.
  virtual void design_done(const storage::ExperimentDesign&, double /*mean_score*/) {}
};

struct ExperimentRunOptions {
  unsigned threads = 0;          // 0: all cores
  Evaluator* evaluator = nullptr;
  ExperimentObserver* observer = nullptr;
  const CancelToken* cancel = nullptr;
};

struct ExperimentOutcome {
  bool cancelled = false;
  int designs_done = 0, designs = 0;
  double wall_seconds = 0.0;
};

ExperimentOutcome run_experiment(StartedExperiment& experiment, const ExperimentRunOptions& options);

/// Scores a design's final control software on the protocol's assessment seeds — in the design
/// model and, when the protocol asks, on the same seeds in each pseudo-reality sample — and
/// records it all at once: the design is done. (A cluster experiment's designs are assessed
/// here when they come home.)
void assess_design(storage::Experiments& store, const storage::ExperimentDesign& design,
                   const experiments::Protocol& protocol, const ExperimentRunOptions& options);

/// A project's experiments with their progress (status, the web monitor). A pure read: it starts
/// no process and no simulation; a cluster experiment shows what collect_cluster_experiments
/// (cluster_experiments.hpp) last brought home.
struct ExperimentProgress {
  storage::Experiment experiment;
  int designs = 0, designs_done = 0;
  std::optional<storage::ExperimentDesign> current;  // the design being made (or last stopped)
  std::optional<storage::DesignProgress> current_race;  // its race so far, once it has one
};
std::vector<ExperimentProgress> experiments_progress(Home& home, const storage::User& user,
                                                     const std::optional<std::string>& project = std::nullopt);

/// The protocol experiment `name` of the project was started with (it resumes with that one);
/// NotFound naming the experiments the project has.
experiments::Protocol stored_protocol(Home& home, const storage::User& user, const std::optional<std::string>& project,
                                      const std::string& name);

}  // namespace sd::app
