#include "cli/design_run.hpp"

#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command_registry.hpp"
#include "cli/mission_input.hpp"
#include "cli/progress_display.hpp"
#include "cli/resumable_runs.hpp"
#include "cli/simulation_runner.hpp"
#include "control/config_string.hpp"
#include "control/describe.hpp"
#include "design/race_log.hpp"
#include "evaluation/results_version.hpp"
#include "missions/catalogue.hpp"

namespace sd::cli {

namespace {

using storage::DesignFolderError;

design::IraceOptions engine_options(long long budget, std::uint64_t seed) {
  design::IraceOptions o;
  o.max_experiments = budget;
  o.seed = seed;
  o.n_instances = 1;  // one mission; every position of the instance list has its own seed
  return o;
}

// Fingerprints need an engine, and an engine needs a runner; this one is never called.
struct NoRunner final : design::ExperimentRunner {
  void run(std::span<const design::Experiment>, std::span<double>) override {}
};

std::string fingerprint(const design::ParameterSpace& space, const design::IraceOptions& options) {
  NoRunner none;
  return design::IteratedRace(space, options, none).fingerprint();
}

/// design-<mission>-seed<S>, or with -2, -3 ... when taken: a design never lands in an old one.
std::filesystem::path default_design_folder(const std::string& mission_name, std::uint64_t seed) {
  const std::string base = "design-" + mission_name + "-seed" + std::to_string(seed);
  std::filesystem::path folder = base;
  for (int n = 2; std::filesystem::exists(folder); ++n) folder = base + "-" + std::to_string(n);
  return folder;
}

}  // namespace

std::string mission_reference(const std::string& mission) {
  const bool is_path = mission.find('/') != std::string::npos || mission.ends_with(".json");
  return is_path ? std::filesystem::absolute(mission).lexically_normal().string() : mission;
}

long long minimum_design_budget(const design::ParameterSpace& space, int nb_iterations) {
  const int n = design::default_nb_iterations(space.nb_variable());
  return design::minimum_budget(engine_options(1, 0), n, nb_iterations > 0 ? nb_iterations : n);
}

void require_minimum_budget(long long budget, const design::ParameterSpace& space, int nb_iterations) {
  const long long minimum = minimum_design_budget(space, nb_iterations);
  if (budget < minimum)
    throw UsageError("a budget of " + std::to_string(budget) + " simulation runs is below the minimum of " +
                     std::to_string(minimum) + " that Iterated F-Race needs for this design space" +
                     (nb_iterations > 0 ? " with " + std::to_string(nb_iterations) + " iterations" : ""));
}

PreparedDesign check_new_design(const NewDesignSettings& settings) {
  PreparedDesign d;
  d.mission = load_mission_or_usage(settings.mission);
  d.mission_reference = mission_reference(settings.mission);
  try {
    d.choice = design::resolve_design_space(settings.space);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  d.space = std::make_unique<design::ParameterSpace>(design::build_design_space(d.choice));
  require_minimum_budget(settings.budget, *d.space);
  d.options = engine_options(settings.budget, settings.seed);
  return d;
}

PreparedDesign prepare_new_design(const NewDesignSettings& settings, const std::filesystem::path& folder) {
  PreparedDesign d = check_new_design(settings);
  d.folder = std::filesystem::absolute(folder.empty() ? default_design_folder(d.mission.name, settings.seed) : folder)
                 .lexically_normal();
  if (std::filesystem::exists(storage::DesignStore::file_in(d.folder)))
    throw DesignFolderError(d.folder.string() + " already holds a design; continue it with --resume " + d.folder.string());
  return d;
}

PreparedDesign prepare_resume(const std::filesystem::path& folder, bool allow_finished) {
  PreparedDesign d;
  d.folder = std::filesystem::absolute(folder).lexically_normal();
  d.resuming = true;
  storage::DesignStore store = storage::DesignStore::open(d.folder, true);
  const storage::DesignMeta& meta = store.meta();
  d.mission_reference = meta.mission;
  ResumeCheck check =
      check_resumable("the design in " + d.folder.string(), meta.mission, meta.mission_digest, meta.results_version);
  if (!check.refusal.empty()) throw DesignFolderError(check.refusal);
  d.mission = std::move(check.mission);
  try {
    d.choice = design::resolve_design_space(design::request_from_text(meta.architectures, meta.flavours));
  } catch (const std::invalid_argument& e) {
    throw DesignFolderError("the design in " + d.folder.string() + " uses a design space this swarmdesign lacks: " + e.what());
  }
  d.space = std::make_unique<design::ParameterSpace>(design::build_design_space(d.choice));
  d.options = engine_options(meta.budget, meta.seed);
  if (fingerprint(*d.space, d.options) != meta.fingerprint)
    throw DesignFolderError("the design in " + d.folder.string() +
                            " was made with another design space or other optimiser settings than this swarmdesign has; "
                            "it cannot be resumed by this version");
  d.restored = store.load_state();
  if (d.restored && d.restored->phase == design::Phase::Finished && !allow_finished)
    throw DesignFolderError("the design in " + d.folder.string() + " has already finished; nothing to resume");
  return d;
}

DesignReport run_prepared_design(PreparedDesign& d, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::filesystem::create_directories(d.folder);
  const storage::DesignRunLock lock(d.folder);
  storage::DesignStore store = [&] {
    if (d.resuming) return storage::DesignStore::open(d.folder);
    storage::DesignMeta meta{d.mission_reference, std::string(direction_name(d.mission.objective.direction)),
                             d.options.max_experiments, d.choice.architectures_text(), d.choice.flavours_text(),
                             d.options.seed, fingerprint(*d.space, d.options), d.mission.digest, kResultsVersion};
    return storage::DesignStore::create(d.folder, meta);
  }();

  SimulationRunner runner(d.mission, *d.space, options.threads);
  design::IteratedRace race(*d.space, d.options, runner);
  design::EliminationTracker eliminations;
  if (d.restored) {
    race.restore(std::move(*d.restored));
    d.restored.reset();
    eliminations.reset(race.state());
  }
  const bool maximise = d.mission.objective.direction == Direction::Maximize;
  ProgressDisplay display(options.progress         ? ProgressDisplay::Mode::Terminal
                          : options.log_iterations ? ProgressDisplay::Mode::Log
                                                   : ProgressDisplay::Mode::Off,
                          maximise);
  race.on_progress([&](const design::Progress& p) {
    eliminations.observe(race.state());
    display.update(p);
  });
  race.on_checkpoint([&](const design::Checkpoint& c) {
    const auto dropped = eliminations.take();
    store.save(c, dropped, *d.space);
  });
  const design::DesignResult result = race.run();
  display.clear();

  DesignReport r;
  r.folder = d.folder;
  r.mission = d.mission.name;
  r.direction = std::string(direction_name(d.mission.objective.direction));
  r.budget = d.options.max_experiments;
  r.seed = d.options.seed;
  r.architectures = d.choice.architectures_text();
  r.flavours = d.choice.flavours_text();
  r.notes = d.choice.notes;
  r.resumed = d.resuming;
  r.experiments_used = result.experiments_used;
  r.iterations = result.iterations;
  r.finish_reason = result.finish_reason;
  for (const auto& e : result.elites)
    r.elites.push_back({e.id, d.space->render(e.configuration), runner.score_of(e.mean_cost), e.evaluations});
  if (r.elites.empty()) throw std::runtime_error("the design ended without a best configuration");
  r.best = parse_control_software(r.elites.front().configuration);
  r.threads = runner.threads();
  r.evaluation_seconds = runner.evaluation_seconds();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void print_design_report(const DesignReport& r, bool as_json) {
  const EliteReport& best = r.elites.front();
  if (as_json) {
    nlohmann::json elites = nlohmann::json::array();
    for (const auto& e : r.elites)
      elites.push_back({{"id", e.id}, {"configuration", e.configuration}, {"mean_score", e.mean_score},
                        {"evaluations", e.evaluations}});
    const double overhead = r.wall_seconds > 0 ? (r.wall_seconds - r.evaluation_seconds) / r.wall_seconds : 0.0;
    nlohmann::json out{{"folder", r.folder.string()},
                       {"mission", r.mission},
                       {"direction", r.direction},
                       {"budget", r.budget},
                       {"seed", r.seed},
                       {"architectures", r.architectures},
                       {"flavours", r.flavours},
                       {"resumed", r.resumed},
                       {"experiments_used", r.experiments_used},
                       {"iterations", r.iterations},
                       {"finish_reason", r.finish_reason},
                       {"best", elites.front()},
                       {"elites", elites},
                       {"timing", {{"wall_s", r.wall_seconds}, {"evaluation_s", r.evaluation_seconds},
                                   {"optimiser_overhead", overhead}, {"threads", r.threads}}}};
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::cout << "Design finished (" << r.finish_reason << "): " << r.experiments_used << " of " << r.budget
            << " simulation runs, " << r.iterations << " iterations, seed " << r.seed << ".\n"
            << "Best control software (configuration " << best.id << "): mean score " << format_number(best.mean_score)
            << " on " << r.mission << " (" << r.direction << ") over " << best.evaluations << " runs\n"
            << describe(r.best) << "Configuration string:\n  " << best.configuration << "\n"
            << "Design folder: " << r.folder.string() << "\n";
}

}  // namespace sd::cli
