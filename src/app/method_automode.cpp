// AutoMoDe as a design method: Iterated F-Race over the condition's modular design space, made
// by the design job (design_job.hpp) in the design's folder, where design.db keeps everything.
#include "app/design_job.hpp"

#include <nlohmann/json.hpp>

#include "app/design_method.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "control/config_string.hpp"
#include "design/sampling.hpp"
#include "storage/design_store.hpp"

namespace sd::app {

namespace {

/// The space of a condition and the smallest budget its method accepts for it.
std::pair<design::DesignSpaceChoice, long long> condition_space(const experiments::Condition& c,
                                                                const design::MethodInfo& method) {
  const auto choice = resolve_space(design::request_from_names(c.architectures, c.flavours));
  return {choice, minimum_design_budget(method, design::build_design_space(choice))};
}

/// Shows a design's race steps to the method's observer in the mission's units.
class RaceWatcher final : public DesignObserver {
 public:
  RaceWatcher(bool maximise, MethodObserver* observer) : maximise_(maximise), observer_(observer) {}
  void progress(const design::Progress& p) override {
    if (p.best_id == 0 || !observer_) return;  // a race that has not scored anyone yet
    observer_->progress(p.experiments_used, maximise_ ? -p.best_mean : p.best_mean);
  }
  void checkpoint(std::int64_t step) override {
    if (observer_) observer_->checkpoint(step);
  }

 private:
  bool maximise_;
  MethodObserver* observer_;
};

/// AutoMoDe's design space and design job, raced by the optimiser of `info` (automode's
/// Iterated F-Race, random search or local search: design/method_options.hpp).
class AutoMoDe final : public DesignMethod {
 public:
  explicit AutoMoDe(const design::MethodInfo& info) : info_(info) {}
  const design::MethodInfo& info() const override { return info_; }

  std::optional<std::string> plan(storage::PlannedDesign& d, const experiments::Condition& c) const override {
    const auto [choice, minimum] = condition_space(c, info_);
    d.architectures = choice.architectures_text();
    d.flavours = choice.flavours_text();
    if (d.budget >= minimum) return std::nullopt;
    const std::string note = "budget " + std::to_string(d.budget) +
                             " is below the optimiser's minimum for this space; it runs with " + std::to_string(minimum);
    d.budget = minimum;
    return note;
  }

  std::vector<ControlSoftware> samples(const experiments::Condition& c, Rng& rng) const override {
    const auto space = design::build_design_space(condition_space(c, info_).first);
    std::vector<ControlSoftware> out;
    out.reserve(4);
    for (int i = 0; i < 4; ++i) out.push_back(parse_control_software(space.render(design::sample_uniform(space, rng))));
    return out;
  }

  std::optional<MadeDesign> run(const storage::PlannedDesign& d, const std::filesystem::path& folder,
                                const MethodRunOptions& options) const override {
    PreparedDesign prepared =
        std::filesystem::exists(storage::DesignStore::file_in(folder))
            ? prepare_resume(folder, true)
            : prepare_new_design({d.mission, d.budget, design::request_from_text(d.architectures, d.flavours), d.seed,
                                  FileScope::local(), {}, std::string(kDefaultDesignSamples), {}, &info_},
                                 folder);
    RaceWatcher watcher(prepared.mission.objective.direction == Direction::Maximize, options.observer);
    const DesignOutcome outcome = run_design(
        prepared, {.threads = options.threads, .evaluator = options.evaluator, .observer = &watcher, .cancel = options.cancel});
    if (outcome.cancelled) return std::nullopt;
    const EliteReport& best = outcome.report->elites.front();
    return MadeDesign{best.configuration, best.mean_score, outcome.experiments_used};
  }

  std::vector<storage::ConvergencePoint> convergence(const std::filesystem::path& folder) const override {
    return storage::read_convergence(folder);  // the race's own record, at the end of every iteration
  }

  nlohmann::json document(const std::filesystem::path& folder) const override {
    return stored_progress_document(storage::read_design_progress(folder));
  }

  std::string describe(const storage::PlannedDesign& d) const override {
    return d.architectures + " / " + d.flavours + (&info_ == &design::kAutoMoDe ? "" : " / " + std::string(info_.name));
  }
  bool runs_on_cluster() const override { return true; }

 private:
  const design::MethodInfo& info_;
};

}  // namespace

const DesignMethod& automode_method() {
  static const AutoMoDe method(design::kAutoMoDe);
  return method;
}

const DesignMethod& random_search_method() {
  static const AutoMoDe method(design::kRandomSearch);
  return method;
}

const DesignMethod& local_search_method() {
  static const AutoMoDe method(design::kLocalSearch);
  return method;
}

}  // namespace sd::app
