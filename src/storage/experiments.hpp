#pragma once
// The experiments of one project: the protocol as run, its designs (one per mission,
// condition and replicate) with their stage, final control software, convergence and the
// scores of their assessment on fresh seeds. A running experiment is leased by the job that
// runs it (storage/lease.hpp), like a design, so a killed one is found interrupted and resumed.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "storage/designs.hpp"
#include "storage/lease.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"

namespace sd::storage {

struct Experiment {
  std::int64_t id = 0;
  std::string name;
  std::string protocol;          // JSON text, as run
  DesignState state = DesignState::running;
  std::string owner;
  std::int64_t heartbeat_at = 0;
  std::filesystem::path folder;  // absolute
  std::int64_t created_at = 0, updated_at = 0;
  std::optional<std::int64_t> finished_at;
};

enum class DesignStage { pending, designing, assessing, done };
std::string to_string(DesignStage stage);

/// A design the protocol asks for, before it runs.
struct PlannedDesign {
  std::string mission, condition;
  int replicate = 1;
  std::string method;                  // a design method's name (design/methods.hpp)
  std::string architectures, flavours; // as the designs table writes them ("" for evostick)
  std::int64_t budget = 0;
  std::uint64_t seed = 0;
};

struct ExperimentDesign {
  std::int64_t id = 0;
  PlannedDesign plan;
  DesignStage stage = DesignStage::pending;
  std::filesystem::path folder;        // absolute: <experiment folder>/<id>
  std::optional<std::string> configuration;
  std::optional<double> design_score;
  std::optional<std::int64_t> runs_used;
  double wall_seconds = 0.0;
  std::optional<std::int64_t> reused_from;  // the twin whose result it took
};

/// A final design's score in one pseudo-reality sample with one seed.
struct RealityScore {
  std::uint64_t sample = 0, seed = 0;
  double score = 0.0;
};

class Experiments {
 public:
  /// The experiments of a project obtained through Projects (so already owned by the user).
  Experiments(Workspace& workspace, Project project);

  /// Records a new experiment with its designs (all pending), owned by `owner`; or, when one of
  /// that name exists and is interrupted, takes it over (it resumes). Conflict when it is still
  /// running, or was made with another protocol (then it names the difference's remedy).
  /// Returns the experiment and whether it was resumed.
  std::pair<Experiment, bool> start(const std::string& name, const std::string& protocol,
                                    const std::vector<PlannedDesign>& designs, const std::string& owner);
  bool heartbeat(std::int64_t experiment_id, const std::string& owner);
  void finish(std::int64_t experiment_id);
  /// The owner stops: the experiment becomes interrupted and resumes when started again.
  /// Conflict when the owner does not hold it (storage/lease.hpp), as for a design.
  void release(std::int64_t experiment_id, const std::string& owner);

  std::optional<Experiment> find(const std::string& name);
  /// NotFound naming the experiments the project has.
  Experiment get(const std::string& name);
  std::vector<Experiment> list();

  std::vector<ExperimentDesign> designs(std::int64_t experiment_id);
  /// A design of any experiment of the project (the twin a design reused); NotFound otherwise.
  ExperimentDesign design(std::int64_t design_id);
  void set_stage(std::int64_t design_id, DesignStage stage);
  /// A design of another experiment of the project that is the same design (mission, method,
  /// space, budget and seed) and has its final control software; with the experiment's name.
  std::optional<std::pair<ExperimentDesign, std::string>> finished_twin(const ExperimentDesign& design);
  /// Takes the twin's result (control software, estimate, runs, wall time, convergence): the
  /// design goes on to assessment.
  void reuse(std::int64_t design_id, const ExperimentDesign& twin);
  /// The design's final control software: it goes on to assessment.
  void design_finished(std::int64_t design_id, const std::string& configuration, double design_score,
                       std::int64_t runs_used);
  void add_wall_seconds(std::int64_t design_id, double seconds);
  /// Every assessment score at once (in the design model, and in pseudo-reality samples when
  /// the protocol asks for them), and the design is done: one transaction.
  void record_assessment(std::int64_t design_id, const std::vector<std::uint64_t>& seeds,
                         const std::vector<double>& scores, const std::vector<RealityScore>& reality = {});
  std::vector<std::pair<std::uint64_t, double>> assessments(std::int64_t design_id);
  /// Its pseudo-reality scores, by sample then seed (none for a protocol without them).
  std::vector<RealityScore> reality_assessments(std::int64_t design_id);

 private:
  Lease lease();
  Experiment get_by_id(std::int64_t id);
  /// Only designs of this project's experiments may be touched.
  void require_design(std::int64_t design_id);

  Workspace& workspace_;
  Project project_;
};

}  // namespace sd::storage
