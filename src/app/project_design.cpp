#include "app/project_design.hpp"

#include <nlohmann/json.hpp>

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/lease_keeper.hpp"
#include "app/projects.hpp"
#include "core/bounded_file.hpp"
#include "core/durable_file.hpp"
#include "control/config_string.hpp"
#include "evaluation/results_version.hpp"
#include "missions/catalogue.hpp"
#include "storage/design_store.hpp"
#include "storage/lease.hpp"

namespace sd::app {

namespace {

/// Renews a running design's lease until it ends.
LeaseKeeper design_lease(const ProjectDesign& d) {
  return LeaseKeeper(d.home, [project = d.project, id = d.design.id, owner = d.design.owner](Home& home) {
    storage::Designs(home.workspace(), project).heartbeat(id, owner);
  });
}

/// Whether `prepared`, seeded `seed`, would run exactly as `finished` ran.
bool repeats(const storage::Design& finished, const PreparedDesign& prepared, std::uint64_t seed, std::int64_t budget) {
  if (finished.state != storage::DesignState::finished || finished.seed != seed || finished.budget != budget ||
      finished.mission != prepared.mission_reference || finished.architectures != prepared.choice.architectures_text() ||
      finished.flavours != prepared.choice.flavours_text() || finished.method != prepared.method->name)
    return false;
  try {  // the same mission file may have been edited since, or the build may score otherwise
    const storage::DesignMeta meta = storage::DesignStore::open(finished.folder).meta();
    const bool same_models = prepared.reality ? meta.pseudo_reality_document == prepared.reality->document &&
                                                    meta.pseudo_reality_samples == prepared.reality_samples
                                              : meta.pseudo_reality.empty();
    return !meta.mission_digest.empty() && meta.mission_digest == prepared.mission.digest &&
           meta.results_version == kResultsVersion && same_models;
  } catch (const std::exception&) {
    return false;
  }
}

/// A robust design's pseudo-realities, kept in its folder from the start: a design killed
/// before design.db exists starts again from its row, which does not hold them.
constexpr const char* kPseudoRealityFile = "pseudo-reality.json";

void remember_pseudo_reality(const PreparedDesign& d) {
  std::filesystem::create_directories(d.folder);
  const nlohmann::json doc = {{"reference", d.reality->reference},
                              {"document", d.reality->document},
                              {"samples", d.reality_samples}};
  replace_file_durably(d.folder / kPseudoRealityFile, doc.dump(), 0600, Umask::Applies);
}

NewDesignSettings interrupted_settings(const storage::Design& latest, const FileScope& files) {
  NewDesignSettings settings{latest.mission, latest.budget, design::request_from_text(latest.architectures, latest.flavours),
                             latest.seed, files, {}, std::string(kDefaultDesignSamples), {}, &search_method(latest.method)};
  const std::filesystem::path remembered = latest.folder / kPseudoRealityFile;
  if (!std::filesystem::exists(remembered)) return settings;
  const nlohmann::json doc =
      nlohmann::json::parse(read_folder_file(latest.folder, kPseudoRealityFile, "pseudo-reality file").text);
  const NamedPseudoReality reality =
      pseudo_reality_from_document(doc.at("reference").get<std::string>(), doc.at("document").get<std::string>());
  // Resumed from its own copy: a shipped name or file edited since cannot change it.
  settings.pseudo_reality = reality.reference;
  settings.pseudo_reality_document = reality.document;
  settings.pseudo_reality_samples = doc.at("samples").get<std::string>();
  return settings;
}

}  // namespace

AlreadyFinished::AlreadyFinished(storage::Design finished, const std::string& project)
    : storage::Conflict("design " + std::to_string(finished.id) + " of " + project + " already finished with this mission, budget, " +
               "design space and seed " + std::to_string(finished.seed) +
               ": it would only repeat it (run-design --new, or fresh in the web API, designs it again)"),
      design(std::move(finished)) {}

bool resumes(const std::optional<storage::Design>& latest, bool fresh) {
  return latest && latest->state == storage::DesignState::interrupted && !fresh;
}

ProjectDesign start_project_design(Home& home, const storage::User& user, const ProjectDesignRequest& request) {
  storage::Workspace& workspace = home.workspace();
  storage::Projects projects(workspace, user);
  storage::Project project = request.project ? projects.get(*request.project) : projects.require_active();
  if (project.cluster)
    throw InvalidRequest("project " + project.name + " runs on a cluster: its designs are submitted to Slurm with "
                         "swarmdesign run-design");
  storage::Designs designs(workspace, project);
  const auto latest = designs.latest();

  if (resumes(latest, request.fresh)) {
    PreparedDesign prepared;
    try {
      prepared = std::filesystem::exists(storage::DesignStore::file_in(latest->folder))
                     ? prepare_resume(latest->folder, true, request.files)
                     : prepare_new_design(interrupted_settings(*latest, request.files),
                                          latest->folder);  // killed before its first checkpoint
    } catch (const std::exception& e) {
      throw DesignFolderError("design " + std::to_string(latest->id) + " of " + project.name +
                              " was interrupted and cannot be resumed: " + e.what() +
                              " (run-design --new gives it up and starts a new design)");
    }
    storage::Design resumed = designs.resume(latest->id, request.owner);
    return {workspace.home(), project, resumed, std::move(prepared), true, std::nullopt};
  }

  // Said in the project's words, not as the file rule's refusal of a path the user never typed.
  if (const auto problem = mission_problem(project))
    throw NotFound("project " + project.name + ": " + *problem +
                   "; choose another mission (swarmdesign set-mission, or Set mission on the Designs tab)");
  const std::uint64_t seed = request.seed ? *request.seed : random_seed();
  std::optional<PreparedDesign> checked;
  if (project.mission && project.budget)  // else Designs::start says what is missing
    checked = check_new_design({*project.mission, *project.budget, request.space, seed, request.files,
                                request.pseudo_reality, request.pseudo_reality_samples, {}, request.method});
  if (checked && latest && request.seed && !request.fresh && repeats(*latest, *checked, seed, *project.budget))
    throw AlreadyFinished(*latest, project.name);
  const design::DesignSpaceChoice choice = checked ? checked->choice : resolve_space(request.space);
  std::optional<storage::Design> abandoned;
  if (checked && latest && latest->state == storage::DesignState::interrupted && request.fresh) {
    designs.abandon(latest->id);
    abandoned = latest;
  }
  storage::Design design =
      designs.start({choice.architectures_text(), choice.flavours_text(), seed, request.owner, std::string(request.method->name)});
  if (!checked) throw std::logic_error("a design started without a mission or budget");
  PreparedDesign prepared = std::move(*checked);
  prepared.folder = design.folder;
  if (prepared.reality) remember_pseudo_reality(prepared);
  return {workspace.home(), project, design, std::move(prepared), false, abandoned};
}

DesignOutcome run_project_design(ProjectDesign& d, const DesignRunOptions& options) {
  DesignOutcome outcome;
  {
    LeaseKeeper lease = design_lease(d);
    try {
      outcome = run_design(d.prepared, options);
    } catch (...) {
      lease.stop();
      Home home(d.home);
      storage::Designs(home.workspace(), d.project).mark_failed(d.design.id);
      throw;
    }
  }
  Home home(d.home);
  storage::Designs designs(home.workspace(), d.project);
  if (outcome.cancelled) designs.release(d.design.id, d.design.owner);
  else designs.finish(d.design.id, outcome.report->elites.front().configuration, outcome.report->elites.front().mean_score);
  return outcome;
}

void hand_over(ProjectDesign& d, const std::string& new_owner) {
  Home home(d.home);
  storage::Designs(home.workspace(), d.project).set_owner(d.design.id, new_owner);
  d.design.owner = new_owner;
}

}  // namespace sd::app
