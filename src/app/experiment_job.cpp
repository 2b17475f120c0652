#include "app/experiment_job.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>

#include "app/design_method.hpp"
#include "app/assess_job.hpp"
#include "app/errors.hpp"
#include "app/evaluation_job.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "app/lease_keeper.hpp"
#include "app/projects.hpp"
#include "app/pseudo_realities.hpp"
#include "control/config_string.hpp"
#include "core/fnv.hpp"
#include "core/rng.hpp"
#include "missions/catalogue.hpp"
#include "statistics/descriptive.hpp"

namespace sd::app {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// A design's seed: a function of the protocol's seed and what the design is, so that the
/// same protocol gives the same designs, and reordering or filtering missions changes none.
std::uint64_t design_seed(const experiments::Protocol& protocol, const std::string& mission, const std::string& condition,
                          int replicate) {
  Fnv1a h;
  h.add_u64(protocol.seed);
  h.add(mission);
  h.add(static_cast<unsigned char>(0));
  h.add(condition);
  h.add_u64(static_cast<std::uint64_t>(replicate));
  return h.value() % 2'000'000'000ULL + 1;  // a seed as people type them
}

std::string where(const experiments::MissionPlan& m, const experiments::Condition& c) {
  return "mission " + m.mission + ", condition " + c.name;
}

/// Shows a design's progress to the experiment's observer.
class DesignWatcher final : public MethodObserver {
 public:
  DesignWatcher(const storage::ExperimentDesign& design, ExperimentObserver* observer)
      : design_(design), observer_(observer) {}
  void progress(std::int64_t runs_used, double best_score) override {
    if (observer_) observer_->design_progress(runs_used, design_.plan.budget, best_score);
  }
  void checkpoint(std::int64_t step) override {
    if (observer_) observer_->checkpoint(step);
  }

 private:
  const storage::ExperimentDesign& design_;
  ExperimentObserver* observer_;
};

/// Makes one design with its method (or resumes it from its folder); false when cancelled.
bool make_design(storage::Experiments& store, const storage::ExperimentDesign& d, const ExperimentRunOptions& options) {
  DesignWatcher watcher(d, options.observer);
  const std::optional<MadeDesign> made = design_method(d.plan.method).run(
      d.plan, d.folder,
      {.threads = options.threads, .evaluator = options.evaluator, .observer = &watcher, .cancel = options.cancel});
  if (!made) return false;
  store.design_finished(d.id, made->control_software, made->design_score, made->runs_used);
  return true;
}

/// The pseudo-reality a planned protocol holds.
NamedPseudoReality reality_spec(const experiments::PseudoRealityPlan& plan) {
  if (plan.definition.empty())
    throw InvalidRequest("pseudo_reality.spec: '" + plan.spec + "' was not read when the experiment was planned");
  try {
    return pseudo_reality_from_document(plan.spec, plan.definition);
  } catch (const InvalidRequest& e) {
    throw InvalidRequest(std::string("pseudo_reality.definition: ") + e.what());
  }
}

}  // namespace

void assess_design(storage::Experiments& store, const storage::ExperimentDesign& d, const experiments::Protocol& protocol,
                   const ExperimentRunOptions& options) {
  const Mission mission = load_mission(d.plan.mission);
  const ControlSoftware software = parse_control_software(d.configuration.value());
  const std::vector<std::uint64_t> seeds = assessment_seeds(protocol.assessment_seeds);
  std::function<void(std::size_t, std::size_t)> progress;
  if (options.observer) progress = [&](std::size_t done, std::size_t all) { options.observer->assessing(done, all); };
  std::vector<double> scores;
  std::vector<storage::RealityScore> reality;
  if (const auto& r = protocol.pseudo_reality) {
    // The design model and every sample on the same seeds, in one batch of runs.
    AssessRequest request;
    request.software = {{"design", software}};
    request.spec = reality_spec(*r).spec;
    request.spec_reference = r->spec;
    for (int k = 1; k <= r->samples; ++k) request.samples.push_back(static_cast<std::uint64_t>(k));
    request.seeds = seeds;
    request.threads = static_cast<int>(options.threads);
    request.evaluator = options.evaluator;
    request.progress = progress;
    const Assessment a = assess(mission, request);
    scores = a.software.at(0).design_scores;
    const std::vector<double>& in_reality = a.software.at(0).reality_scores;
    for (std::size_t k = 0; k < request.samples.size(); ++k)
      for (std::size_t s = 0; s < seeds.size(); ++s)
        reality.push_back({request.samples[k], seeds[s], in_reality.at(k * seeds.size() + s)});
  } else {
    scores = score_seeds(mission, software, seeds,
                         {.threads = static_cast<int>(options.threads), .evaluator = options.evaluator, .progress = progress});
  }
  store.record_assessment(d.id, seeds, scores, reality);
  if (options.observer)
    options.observer->design_done(d, statistics::mean(scores));
}

std::string mission_label(const std::string& reference) {
  return is_mission_file(reference) ? std::filesystem::path(reference).stem().string() : reference;
}

std::vector<std::uint64_t> assessment_seeds(int count) {
  std::vector<std::uint64_t> seeds(static_cast<std::size_t>(std::max(0, count)));
  std::iota(seeds.begin(), seeds.end(), 3'000'000'001ULL);
  return seeds;
}

PlannedExperiment plan_experiment(const experiments::Protocol& protocol, const FileScope& scope) {
  PlannedExperiment plan;
  plan.protocol = protocol;
  if (auto& r = plan.protocol.pseudo_reality) {
    if (r->definition.empty()) {
      try {
        r->definition = nlohmann::json::parse(load_requested_pseudo_reality(r->spec, scope).document, nullptr, true, true).dump();
      } catch (const InvalidRequest& e) {
        throw InvalidRequest(std::string("pseudo_reality.spec: ") + e.what());
      } catch (const NotFound& e) {
        throw InvalidRequest(std::string("pseudo_reality.spec: ") + e.what());
      }
    }
    reality_spec(*r);  // InvalidRequest naming the field for a malformed inline one
  }
  const std::int64_t runs_per_assessment =
      static_cast<std::int64_t>(protocol.assessment_seeds) * (1 + (protocol.pseudo_reality ? protocol.pseudo_reality->samples : 0));
  for (const auto& m : protocol.missions) {
    load_requested_mission(m.mission);  // InvalidRequest naming the mission (or its file's field)
    const std::string mission = mission_reference(m.mission);
    for (const auto& c : m.conditions) {
      storage::PlannedDesign d{mission, c.name, 1, c.method, "", "", experiments::scaled_budget(protocol, m), 0};
      try {
        if (const auto note = design_method(c.method).plan(d, c)) plan.notes.push_back(where(m, c) + ": " + *note);
      } catch (const std::exception& e) {
        throw InvalidRequest(where(m, c) + ": " + e.what());
      }
      for (int r = 1; r <= protocol.designs; ++r) {
        d.replicate = r;
        d.seed = design_seed(protocol, m.mission, c.name, r);
        plan.designs.push_back(d);
        plan.design_runs += d.budget;
        plan.assessment_runs += runs_per_assessment;
      }
    }
  }
  return plan;
}

DurationEstimate estimate_duration(const PlannedExperiment& plan, unsigned threads) {
  DurationEstimate estimate;
  const std::unique_ptr<Evaluator> backend = make_evaluator(static_cast<int>(threads));
  Evaluator& evaluator = *backend;
  estimate.threads = evaluator.workers();
  std::map<std::string, std::int64_t> runs;
  const std::int64_t runs_per_assessment =
      plan.designs.empty() ? 0 : plan.assessment_runs / static_cast<std::int64_t>(plan.designs.size());
  for (const auto& d : plan.designs) runs[d.mission] += d.budget + runs_per_assessment;
  for (const auto& m : plan.protocol.missions) {
    const std::string reference = mission_reference(m.mission);
    const Mission mission = load_mission(reference);
    // Control software as each condition's method first meets it.
    std::vector<ControlSoftware> samples;
    Rng rng(7);
    for (const auto& c : m.conditions) {
      std::vector<ControlSoftware> first;
      try {
        first = design_method(c.method).samples(c, rng);
      } catch (const std::exception& e) {
        throw InvalidRequest(where(m, c) + ": " + e.what());
      }
      samples.insert(samples.end(), first.begin(), first.end());
    }
    const std::vector<std::uint64_t> seeds = {1, 2};
    const auto start = Clock::now();
    std::size_t measured = 0;
    for (const auto& software : samples) {
      score_seeds(mission, software, seeds, {.threads = 0, .evaluator = &evaluator, .progress = {}});
      measured += seeds.size();
    }
    const double per_run = seconds_since(start) / static_cast<double>(measured);
    const std::int64_t mission_runs = runs[reference];
    estimate.missions.push_back({m.mission, mission_runs, per_run});
    estimate.seconds += per_run * static_cast<double>(mission_runs);
  }
  return estimate;
}

StartedExperiment start_experiment(Home& home, const storage::User& user, const PlannedExperiment& plan,
                                   const ExperimentStartRequest& request) {
  storage::Projects projects(home.workspace(), user);
  StartedExperiment started;
  started.home = home.folder();
  started.project = request.project ? projects.get(*request.project) : projects.require_active();
  storage::Experiments experiments(home.workspace(), started.project);
  auto [experiment, existed] = experiments.start(plan.protocol.name, experiments::to_json(plan.protocol).dump(),
                                                 plan.designs, request.owner);
  started.experiment = std::move(experiment);
  started.resumed = existed;
  started.already_finished = started.experiment.state == storage::DesignState::finished;
  return started;
}

ExperimentOutcome run_experiment(StartedExperiment& e, const ExperimentRunOptions& options) {
  const auto started = Clock::now();
  Home home(e.home);
  storage::Experiments store(home.workspace(), e.project);
  const experiments::Protocol protocol = experiments::protocol_from_json(nlohmann::json::parse(e.experiment.protocol));
  const auto designs = store.designs(e.experiment.id);
  ExperimentOutcome outcome;
  outcome.designs = static_cast<int>(designs.size());
  outcome.designs_done = static_cast<int>(
      std::count_if(designs.begin(), designs.end(), [](const auto& d) { return d.stage == storage::DesignStage::done; }));
  if (e.already_finished) return outcome;

  LeaseKeeper lease(e.home, [project = e.project, id = e.experiment.id, owner = e.experiment.owner](Home& h) {
    storage::Experiments(h.workspace(), project).heartbeat(id, owner);
  });
  try {
    for (std::size_t i = 0; i < designs.size(); ++i) {
      storage::ExperimentDesign d = designs[i];
      if (d.stage == storage::DesignStage::done) continue;
      if (options.observer) options.observer->design_started(d, static_cast<int>(i) + 1, outcome.designs);
      auto design_start = Clock::now();
      if (d.stage == storage::DesignStage::pending || d.stage == storage::DesignStage::designing) {
        store.set_stage(d.id, storage::DesignStage::designing);
        if (const auto twin = store.finished_twin(d)) {
          // Runs are deterministic: the same design made again would end the same.
          store.reuse(d.id, twin->first);
          if (options.observer) options.observer->design_reused(twin->first, twin->second);
        } else if (!make_design(store, d, options)) {
          store.add_wall_seconds(d.id, seconds_since(design_start));
          lease.stop();
          store.release(e.experiment.id, e.experiment.owner);
          outcome.cancelled = true;
          outcome.wall_seconds = seconds_since(started);
          return outcome;
        }
        store.add_wall_seconds(d.id, seconds_since(design_start));
        design_start = Clock::now();
      }
      d = store.design(d.id);  // with its final control software
      assess_design(store, d, protocol, options);
      store.add_wall_seconds(d.id, seconds_since(design_start));
      ++outcome.designs_done;
    }
  } catch (...) {
    // Whatever stopped it, what is recorded stays valid: the experiment resumes when run again.
    lease.stop();
    try {
      store.release(e.experiment.id, e.experiment.owner);
    } catch (const std::exception&) {
    }
    throw;
  }
  lease.stop();
  store.finish(e.experiment.id);
  outcome.wall_seconds = seconds_since(started);
  return outcome;
}

std::vector<ExperimentProgress> experiments_progress(Home& home, const storage::User& user,
                                                     const std::optional<std::string>& project) {
  const storage::Project p = project_or_active(home, user, project);
  storage::Experiments store(home.workspace(), p);
  // A read only: a cluster experiment's designs come home through collect_cluster_experiments.
  std::vector<ExperimentProgress> all;
  for (const auto& experiment : store.list()) {
    ExperimentProgress progress{experiment, 0, 0, std::nullopt, std::nullopt};
    for (const auto& d : store.designs(experiment.id)) {
      ++progress.designs;
      if (d.stage == storage::DesignStage::done) ++progress.designs_done;
      else if (!progress.current) progress.current = d;
    }
    // The design being made, followed as `status` follows a design: its race's runs and best.
    if (progress.current && progress.current->stage == storage::DesignStage::designing) try {
        if (std::filesystem::exists(storage::DesignStore::file_in(progress.current->folder)))
          progress.current_race = storage::read_design_progress(progress.current->folder);
      } catch (const storage::DesignFolderError&) {
        // Not committed yet, or an EvoStick design (no race): shown without.
      }
    all.push_back(std::move(progress));
  }
  return all;
}
experiments::Protocol stored_protocol(Home& home, const storage::User& user, const std::optional<std::string>& project,
                                      const std::string& name) {
  const storage::Project p = project_or_active(home, user, project);
  return experiments::protocol_from_json(nlohmann::json::parse(storage::Experiments(home.workspace(), p).get(name).protocol));
}

}  // namespace sd::app
