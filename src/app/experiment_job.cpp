#include "app/experiment_job.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>

#include "app/cluster_experiments.hpp"
#include "app/errors.hpp"
#include "app/evaluation_job.hpp"
#include "app/evolution_job.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "app/lease_keeper.hpp"
#include "app/projects.hpp"
#include "control/config_string.hpp"
#include "core/fnv.hpp"
#include "core/rng.hpp"
#include "design/sampling.hpp"
#include "missions/catalogue.hpp"
#include "statistics/descriptive.hpp"
#include "storage/design_store.hpp"

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

/// The EvoStick settings a budget buys: whole generations of the default population.
evostick::Settings evostick_settings(std::int64_t budget, std::uint64_t seed) {
  evostick::Settings settings;
  settings.generations = static_cast<int>(std::max<std::int64_t>(1, budget / settings.runs_per_generation()));
  settings.seed = seed;
  return settings;
}

std::string where(const experiments::MissionPlan& m, const experiments::Condition& c) {
  return "mission " + m.mission + ", condition " + c.name;
}

/// The space of an automode condition and the smallest budget its optimiser accepts.
std::pair<design::DesignSpaceChoice, long long> condition_space(const experiments::MissionPlan& m,
                                                                 const experiments::Condition& c) {
  try {
    const auto choice = resolve_space(design::request_from_names(c.architectures, c.flavours));
    return {choice, minimum_design_budget(design::build_design_space(choice))};
  } catch (const std::exception& e) {
    throw InvalidRequest(where(m, c) + ": " + e.what());
  }
}

/// Shows a design's race steps to the experiment's observer (its convergence is read from its
/// own design.db when reported).
class DesignWatcher final : public DesignObserver {
 public:
  DesignWatcher(const storage::ExperimentDesign& design, bool maximise, ExperimentObserver* observer)
      : design_(design), maximise_(maximise), observer_(observer) {}

  void progress(const design::Progress& p) override {
    if (p.best_id == 0 || !observer_) return;  // a race that has not scored anyone yet
    observer_->design_progress(p.experiments_used, design_.plan.budget, maximise_ ? -p.best_mean : p.best_mean);
  }
  void checkpoint(std::int64_t step) override {
    if (observer_) observer_->checkpoint(step);
  }

 private:
  const storage::ExperimentDesign& design_;
  bool maximise_;
  ExperimentObserver* observer_;
};

/// Makes one AutoMoDe design (or resumes it from its folder); false when cancelled.
bool make_automode_design(storage::Experiments& store, const storage::ExperimentDesign& d,
                          const ExperimentRunOptions& options) {
  PreparedDesign prepared =
      std::filesystem::exists(storage::DesignStore::file_in(d.folder))
          ? prepare_resume(d.folder, true)
          : prepare_new_design({d.plan.mission, d.plan.budget,
                                design::request_from_text(d.plan.architectures, d.plan.flavours), d.plan.seed},
                               d.folder);
  DesignWatcher watcher(d, prepared.mission.objective.direction == Direction::Maximize, options.observer);
  const DesignOutcome outcome =
      run_design(prepared, {.threads = options.threads, .evaluator = options.evaluator, .observer = &watcher,
                            .cancel = options.cancel});
  if (outcome.cancelled) return false;
  const EliteReport& best = outcome.report->elites.front();
  store.design_finished(d.id, best.configuration, best.mean_score, outcome.experiments_used);
  return true;
}

/// Evolves the EvoStick baseline's network (or resumes the evolution kept in its folder).
void make_evostick_design(storage::Experiments& store, const storage::ExperimentDesign& d,
                          const ExperimentRunOptions& options) {
  const auto state = d.folder / "evolution.json";
  std::filesystem::create_directories(d.folder);
  EvolutionRun run;
  run.threads = static_cast<int>(options.threads);
  const std::int64_t per_generation = evostick_settings(d.plan.budget, d.plan.seed).runs_per_generation();
  run.progress = [&](const evostick::GenerationRecord& g, int) {
    store.record_progress(d.id, g.generation * per_generation, g.best_mean);
    if (options.observer) options.observer->design_progress(g.generation * per_generation, d.plan.budget, g.best_mean);
  };
  run.saved = [&](int generation) {
    if (options.observer) options.observer->checkpoint(generation);
  };
  EvolutionOutcome outcome;
  if (std::filesystem::exists(state)) {
    outcome = resume_evolution(state.string(), run);
  } else {
    EvolutionRequest request;
    request.mission = d.plan.mission;
    request.settings = evostick_settings(d.plan.budget, d.plan.seed);
    request.state = state.string();
    outcome = start_evolution(request, run);
  }
  store.design_finished(d.id, outcome.control_software, outcome.result.best_mean, outcome.result.runs);
}

}  // namespace

void assess_design(storage::Experiments& store, const storage::ExperimentDesign& d, int seeds_count,
                   const ExperimentRunOptions& options) {
  const Mission mission = load_mission(d.plan.mission);
  const ControlSoftware software = parse_control_software(d.configuration.value());
  const std::vector<std::uint64_t> seeds = assessment_seeds(seeds_count);
  ScoreOptions score_options{.threads = static_cast<int>(options.threads), .evaluator = options.evaluator, .progress = {}};
  if (options.observer) score_options.progress = [&](std::size_t done, std::size_t all) { options.observer->assessing(done, all); };
  const std::vector<double> scores = score_seeds(mission, software, seeds, score_options);
  store.record_assessment(d.id, seeds, scores);
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

PlannedExperiment plan_experiment(const experiments::Protocol& protocol) {
  PlannedExperiment plan;
  plan.protocol = protocol;
  for (const auto& m : protocol.missions) {
    load_requested_mission(m.mission);  // InvalidRequest naming the mission (or its file's field)
    const std::string mission = mission_reference(m.mission);
    for (const auto& c : m.conditions) {
      storage::PlannedDesign d{mission, c.name, 1, c.method, "", "", experiments::scaled_budget(protocol, m), 0};
      if (c.method == "evostick") {
        const auto settings = evostick_settings(d.budget, 0);
        const std::int64_t runs = settings.runs();
        if (runs != d.budget)
          plan.notes.push_back(where(m, c) + ": EvoStick evolves whole generations of " +
                               std::to_string(settings.runs_per_generation()) + " runs: budget " + std::to_string(d.budget) +
                               " becomes " + std::to_string(runs));
        d.budget = runs;
      } else {
        const auto [choice, minimum] = condition_space(m, c);
        d.architectures = choice.architectures_text();
        d.flavours = choice.flavours_text();
        if (d.budget < minimum) {
          plan.notes.push_back(where(m, c) + ": budget " + std::to_string(d.budget) +
                               " is below the optimiser's minimum for this space; it runs with " + std::to_string(minimum));
          d.budget = minimum;
        }
      }
      for (int r = 1; r <= protocol.designs; ++r) {
        d.replicate = r;
        d.seed = design_seed(protocol, m.mission, c.name, r);
        plan.designs.push_back(d);
        plan.design_runs += d.budget;
        plan.assessment_runs += protocol.assessment_seeds;
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
  for (const auto& d : plan.designs) runs[d.mission] += d.budget + plan.protocol.assessment_seeds;
  for (const auto& m : plan.protocol.missions) {
    const std::string reference = mission_reference(m.mission);
    const Mission mission = load_mission(reference);
    // Control software as the optimiser first meets it: sampled uniformly from each condition's
    // space (EvoStick's network costs about as much as one Arlequin module).
    std::vector<ControlSoftware> samples;
    Rng rng(7);
    for (const auto& c : m.conditions) {
      if (c.method == "evostick") {
        samples.push_back(parse_control_software("--fsm-config --nstates 1 --s0 50"));
        continue;
      }
      const auto space = design::build_design_space(condition_space(m, c).first);
      for (int i = 0; i < 4; ++i) samples.push_back(parse_control_software(space.render(design::sample_uniform(space, rng))));
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
        } else if (d.plan.method == "evostick") {
          make_evostick_design(store, d, options);
        } else if (!make_automode_design(store, d, options)) {
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
      assess_design(store, d, protocol.assessment_seeds, options);
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
  // A cluster experiment's designs come home (and are assessed) as their tasks end.
  if (p.cluster)
    for (const auto& experiment : store.list()) refresh_cluster_experiment(home, p, experiment);
  std::vector<ExperimentProgress> all;
  for (const auto& experiment : store.list()) {
    ExperimentProgress progress{experiment, 0, 0, std::nullopt};
    for (const auto& d : store.designs(experiment.id)) {
      ++progress.designs;
      if (d.stage == storage::DesignStage::done) ++progress.designs_done;
      else if (!progress.current) progress.current = d;
    }
    all.push_back(std::move(progress));
  }
  return all;
}

nlohmann::json experiments_document(const std::vector<ExperimentProgress>& experiments) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& e : experiments) {
    nlohmann::json item{{"name", e.experiment.name},
                        {"state", storage::to_string(e.experiment.state)},
                        {"designs", e.designs},
                        {"designs_done", e.designs_done}};
    if (e.current)
      item["current"] = {{"mission", mission_label(e.current->plan.mission)},     {"condition", e.current->plan.condition},
                         {"replicate", e.current->plan.replicate}, {"stage", storage::to_string(e.current->stage)},
                         {"budget", e.current->plan.budget},       {"folder", e.current->folder.string()}};
    list.push_back(std::move(item));
  }
  return list;
}

}  // namespace sd::app
