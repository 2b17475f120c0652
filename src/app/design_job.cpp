#include "app/design_job.hpp"

#include <chrono>

#include "app/design_db_checkpoints.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "app/resume_check.hpp"
#include "app/simulation_runner.hpp"
#include "control/config_string.hpp"
#include "design/method_options.hpp"
#include "design/race_log.hpp"
#include "evaluation/results_version.hpp"
#include "missions/catalogue.hpp"
#include "storage/design_store.hpp"

namespace sd::app {

namespace {

/// The method's optimiser settings for a prepared design (its space and instances set): one
/// mission, every position of the instance list with its own seed; a robust design's instances
/// are its pseudo-reality samples.
design::IraceOptions design_options(const PreparedDesign& d, long long budget, std::uint64_t seed) {
  return design::method_options(*d.method, budget, seed, std::max<std::size_t>(1, d.instance_models.size()), *d.space);
}

/// How a refusal names the optimiser: AutoMoDe's by its algorithm, as it always did.
std::string optimiser_name(const design::MethodInfo& method) {
  return &method == &design::kAutoMoDe ? "Iterated F-Race" : std::string(method.name);
}

/// The pseudo-realities of a robust design: the models its instances run in.
void use_pseudo_realities(PreparedDesign& d, NamedPseudoReality reality, const std::string& samples_text) {
  const std::vector<std::uint64_t> samples = parse_sample_range(samples_text);
  if (samples.size() > 1000) throw InvalidRequest("pseudo-reality samples '" + samples_text + "': at most 1,000 for a design");
  d.instance_models.clear();
  for (const std::uint64_t k : samples) d.instance_models.push_back(reality.spec.sample(d.mission.robot, k));
  d.reality_samples = samples_text;
  d.reality = std::move(reality);
}

/// design-<mission>-seed<S>, or with -2, -3 ... when taken: a design never lands in an old one.
std::filesystem::path default_design_folder(const std::string& mission_name, std::uint64_t seed) {
  const std::string base = "design-" + mission_name + "-seed" + std::to_string(seed);
  std::filesystem::path folder = base;
  for (int n = 2; std::filesystem::exists(folder); ++n) folder = base + "-" + std::to_string(n);
  return folder;
}

}  // namespace

long long minimum_design_budget(const design::ParameterSpace& space, int nb_iterations) {
  const int n = design::default_nb_iterations(space.nb_variable());
  return design::minimum_budget(design::IraceOptions{}, n, nb_iterations > 0 ? nb_iterations : n);
}

long long minimum_design_budget(const design::MethodInfo& method, const design::ParameterSpace& space) {
  return design::method_minimum_budget(method, space);
}

void require_minimum_budget(long long budget, const design::ParameterSpace& space, int nb_iterations) {
  const long long minimum = minimum_design_budget(space, nb_iterations);
  if (budget < minimum)
    throw InvalidRequest("a budget of " + std::to_string(budget) + " simulation runs is below the minimum of " +
                         std::to_string(minimum) + " that Iterated F-Race needs for this design space" +
                         (nb_iterations > 0 ? " with " + std::to_string(nb_iterations) + " iterations" : ""));
}

const design::MethodInfo& search_method(std::string_view name) {
  const design::MethodInfo* method = design::find_method(name);
  if (!method || !method->has_design_space)
    throw InvalidRequest("unknown design method '" + std::string(name) + "' (" + search_method_names() + ")");
  return *method;
}

std::string search_method_names() { return design::method_names_text(/*design_space_only=*/true); }

design::DesignSpaceChoice resolve_space(const design::DesignSpaceRequest& request) {
  try {
    return design::resolve_design_space(request);
  } catch (const std::invalid_argument& e) {
    throw InvalidRequest(e.what());
  }
}

PreparedDesign check_new_design(const NewDesignSettings& settings) {
  PreparedDesign d;
  d.mission = load_requested_mission(settings.mission, settings.files);
  d.mission_reference = mission_reference(settings.mission);
  d.choice = resolve_space(settings.space);
  d.space = std::make_unique<design::ParameterSpace>(design::build_design_space(d.choice));
  d.method = settings.method;
  if (const long long minimum = minimum_design_budget(*d.method, *d.space); settings.budget < minimum)
    throw InvalidRequest("a budget of " + std::to_string(settings.budget) + " simulation runs is below the minimum of " +
                         std::to_string(minimum) + " that " + optimiser_name(*d.method) + " needs for this design space");
  if (!settings.pseudo_reality.empty())
    use_pseudo_realities(d,
                         settings.pseudo_reality_document.empty()
                             ? load_requested_pseudo_reality(settings.pseudo_reality, settings.files)
                             : pseudo_reality_from_document(settings.pseudo_reality, settings.pseudo_reality_document),
                         settings.pseudo_reality_samples);
  d.options = design_options(d, settings.budget, settings.seed);
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

namespace {
std::string settings_text(const PreparedDesign& d) {
  std::string text = "mission " + d.mission_reference + ", budget " + std::to_string(d.options.max_experiments) + ", seed " +
                     std::to_string(d.options.seed) + ", " + d.choice.architectures_text() + " / " + d.choice.flavours_text();
  if (d.reality) text += ", pseudo-reality " + d.reality->reference + " samples " + d.reality_samples;
  if (d.method != &design::kAutoMoDe) text += ", method " + std::string(d.method->name);
  return text;
}
}  // namespace

PreparedDesign prepare_design_in(const NewDesignSettings& settings, const std::filesystem::path& folder) {
  if (folder.empty() || !std::filesystem::exists(storage::DesignStore::file_in(folder)))
    return prepare_new_design(settings, folder);
  const PreparedDesign asked = check_new_design(settings);
  PreparedDesign stored = prepare_resume(folder, true, settings.files);
  if (settings_text(stored) != settings_text(asked))
    throw DesignFolderError("the design in " + stored.folder.string() + " was started with other settings (" +
                            settings_text(stored) + "); resume it as it is with --resume " + stored.folder.string() +
                            ", or design in another folder");
  return stored;
}

bool already_finished(const PreparedDesign& d) { return d.restored && d.restored->phase == design::Phase::Finished; }

PreparedDesign prepare_resume(const std::filesystem::path& folder, bool allow_finished, const FileScope& files) {
  PreparedDesign d;
  d.folder = std::filesystem::absolute(folder).lexically_normal();
  d.resuming = true;
  storage::DesignStore store = storage::DesignStore::open(d.folder, true);
  const storage::DesignMeta& meta = store.meta();
  d.mission_reference = meta.mission;
  ResumeCheck check =
      check_resumable("the design in " + d.folder.string(), meta.mission, meta.mission_digest, meta.results_version, files);
  if (!check.refusal.empty()) throw DesignFolderError(check.refusal);
  d.mission = std::move(check.mission);
  try {
    d.choice = design::resolve_design_space(design::request_from_text(meta.architectures, meta.flavours));
  } catch (const std::invalid_argument& e) {
    throw DesignFolderError("the design in " + d.folder.string() + " uses a design space this swarmdesign lacks: " + e.what());
  }
  d.space = std::make_unique<design::ParameterSpace>(design::build_design_space(d.choice));
  if (!meta.pseudo_reality.empty()) {
    try {
      use_pseudo_realities(d, pseudo_reality_from_document(meta.pseudo_reality, meta.pseudo_reality_document),
                           meta.pseudo_reality_samples);
    } catch (const InvalidRequest& e) {
      throw DesignFolderError("the design in " + d.folder.string() + " has pseudo-realities this swarmdesign cannot read: " + e.what());
    }
  }
  d.method = design::find_method(meta.method);
  if (!d.method || !d.method->has_design_space)
    throw DesignFolderError("the design in " + d.folder.string() + " was made by a design method this swarmdesign lacks: " + meta.method);
  d.options = design_options(d, meta.budget, meta.seed);
  if (design::fingerprint(*d.space, d.options) != meta.fingerprint)
    throw DesignFolderError("the design in " + d.folder.string() +
                            " was made with another design space or other optimiser settings than this swarmdesign has; "
                            "it cannot be resumed by this version");
  d.restored = DesignDbCheckpoints(store, *d.space).load();
  if (d.restored && d.restored->phase == design::Phase::Finished && !allow_finished)
    throw DesignFolderError("the design in " + d.folder.string() + " has already finished; nothing to resume");
  return d;
}

DesignOutcome run_design(PreparedDesign& d, const DesignRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::filesystem::create_directories(d.folder);
  const storage::DesignRunLock lock(d.folder);
  storage::DesignStore store = [&] {
    if (d.resuming) return storage::DesignStore::open(d.folder);
    storage::DesignMeta meta{d.mission_reference, std::string(direction_name(d.mission.objective.direction)),
                             d.options.max_experiments, d.choice.architectures_text(), d.choice.flavours_text(),
                             d.options.seed, design::fingerprint(*d.space, d.options), d.mission.digest, kResultsVersion,
                             {}, {}, {}, std::string(d.method->name)};
    if (d.reality) {
      meta.pseudo_reality = d.reality->reference;
      meta.pseudo_reality_document = d.reality->document;
      meta.pseudo_reality_samples = d.reality_samples;
    }
    return storage::DesignStore::create(d.folder, meta);
  }();
  DesignDbCheckpoints checkpoints(store, *d.space);

  std::unique_ptr<Evaluator> own;
  Evaluator& evaluator = options.evaluator ? *options.evaluator : *(own = make_evaluator(static_cast<int>(options.threads)));
  SimulationRunner runner(d.mission, *d.space, evaluator, d.instance_models);
  design::IteratedRace race(*d.space, d.options, runner);
  design::EliminationTracker eliminations;
  if (d.restored) {
    race.restore(std::move(*d.restored));
    d.restored.reset();
    eliminations.reset(race.state());
  }
  race.on_progress([&](const design::Progress& p) {
    eliminations.observe(race.state());
    if (options.observer) options.observer->progress(p);
  });
  race.on_checkpoint([&](const design::Checkpoint& c) {
    const auto dropped = eliminations.take();
    checkpoints.save(c, dropped);
    if (options.observer) options.observer->checkpoint(checkpoints.step());
  });

  DesignOutcome outcome;
  // A cancel stops the race step it falls in between two runs (the step is dropped: the design
  // resumes from the last durable one), so it is heard within a run at any budget.
  struct StopFlag {
    Evaluator& evaluator;
    ~StopFlag() { evaluator.stop_when(nullptr); }
  } stop_flag{evaluator};
  if (options.cancel) evaluator.stop_when(&options.cancel->flag());
  long long durable_experiments = race.state().experiments_used;
  try {
    while (race.advance()) {
      durable_experiments = race.state().experiments_used;
      if (options.cancel && options.cancel->cancelled()) {
        outcome.cancelled = true;
        outcome.experiments_used = durable_experiments;
        return outcome;
      }
    }
  } catch (const EvaluationStopped&) {
    outcome.cancelled = true;
    outcome.experiments_used = durable_experiments;
    return outcome;
  }
  const design::DesignResult result = race.result();
  outcome.experiments_used = result.experiments_used;

  DesignReport r;
  r.folder = d.folder;
  r.mission = d.mission.name;
  r.direction = std::string(direction_name(d.mission.objective.direction));
  r.method = std::string(d.method->name);
  r.budget = d.options.max_experiments;
  r.seed = d.options.seed;
  r.architectures = d.choice.architectures_text();
  r.flavours = d.choice.flavours_text();
  r.notes = d.choice.notes;
  if (d.reality) {
    r.pseudo_reality = d.reality->reference;
    r.pseudo_reality_samples = d.reality_samples;
  }
  r.resumed = d.resuming;
  r.experiments_used = result.experiments_used;
  r.iterations = result.iterations;
  r.finish_reason = result.finish_reason;
  for (const auto& e : result.elites)
    r.elites.push_back({e.id, d.space->render(e.configuration), runner.score_of(e.mean_cost), e.evaluations});
  if (r.elites.empty()) throw std::runtime_error("the design ended without a best configuration");
  r.best = parse_control_software(r.elites.front().configuration);
  r.threads = runner.workers();
  r.evaluation_seconds = runner.evaluation_seconds();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.report = std::move(r);
  return outcome;
}

}  // namespace sd::app
