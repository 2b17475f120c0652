// EvoStick as a design method: whole generations of one network evolved by the evolution job
// (evolution_job.hpp), its state in DIR/evolution.json after every generation and its final
// document, with the history convergence is read from, in DIR/evostick.json.
#include <nlohmann/json.hpp>

#include <fstream>

#include "app/design_method.hpp"
#include "app/evolution_job.hpp"
#include "control/config_string.hpp"
#include "core/bounded_file.hpp"
#include "core/json_integer.hpp"

namespace sd::app {

namespace {

constexpr const char* kStateFile = "evolution.json";
constexpr const char* kDocumentFile = "evostick.json";
/// The network and one line per generation: a few hundred kB for the longest evolution.
constexpr std::size_t kMaxDocumentBytes = std::size_t{16} << 20;

/// The settings a budget buys: whole generations of the default population.
evostick::Settings settings_for(std::int64_t budget, std::uint64_t seed) {
  evostick::Settings settings;
  settings.generations = static_cast<int>(std::max<std::int64_t>(1, budget / settings.runs_per_generation()));
  settings.seed = seed;
  return settings;
}

class EvoStick final : public DesignMethod {
 public:
  const design::MethodInfo& info() const override { return design::kEvoStick; }

  std::optional<std::string> plan(storage::PlannedDesign& d, const experiments::Condition&) const override {
    const auto settings = settings_for(d.budget, 0);
    const std::int64_t runs = settings.runs();
    if (runs == d.budget) return std::nullopt;
    const std::string note = "EvoStick evolves whole generations of " + std::to_string(settings.runs_per_generation()) +
                             " runs: budget " + std::to_string(d.budget) + " becomes " + std::to_string(runs);
    d.budget = runs;
    return note;
  }

  std::vector<ControlSoftware> samples(const experiments::Condition&, Rng&) const override {
    // A network costs about as much as one Arlequin module.
    return {parse_control_software("--fsm-config --nstates 1 --s0 50")};
  }

  std::optional<MadeDesign> run(const storage::PlannedDesign& d, const std::filesystem::path& folder,
                                const MethodRunOptions& options) const override {
    const auto state = folder / kStateFile;
    std::filesystem::create_directories(folder);
    EvolutionRun run;
    run.threads = static_cast<int>(options.threads);
    run.cancel = options.cancel;
    const std::int64_t per_generation = settings_for(d.budget, d.seed).runs_per_generation();
    run.progress = [&](const evostick::GenerationRecord& g, int) {
      if (options.observer) options.observer->progress(g.generation * per_generation, g.best_mean);
    };
    run.saved = [&](int generation) {
      if (options.observer) options.observer->checkpoint(generation);
    };
    const std::string document = (folder / kDocumentFile).string();
    EvolutionOutcome outcome;
    if (std::filesystem::exists(std::filesystem::symlink_status(state))) {
      // Found by itself in the design's folder (a server resumes it): only that folder's own file,
      // never what a link planted at its name leads to. (The CLI's `evolve --state FILE` reads
      // the file its user names, links included.)
      std::error_code error;
      if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(state)) ||
          std::filesystem::hard_link_count(state, error) != 1 || error)
        throw std::runtime_error("the EvoStick design's state file is a link or not a file; it is not read");
      outcome = resume_evolution(state.string(), run, document);
    } else {
      EvolutionRequest request;
      request.mission = d.mission;
      request.settings = settings_for(d.budget, d.seed);
      request.state = state.string();
      request.output = document;
      outcome = start_evolution(request, run);
    }
    if (outcome.cancelled) return std::nullopt;
    return MadeDesign{outcome.control_software, outcome.result.best_mean, outcome.result.runs};
  }

  std::vector<storage::ConvergencePoint> convergence(const std::filesystem::path& folder) const override {
    // Designs made before the document was kept in the folder have no curve, not a broken report.
    if (!std::filesystem::exists(folder / kDocumentFile)) return {};
    const nlohmann::json doc = document(folder);
    const auto& history = doc.at("history");
    if (history.empty()) return {};
    const std::int64_t per_generation = checked_json_integer<std::int64_t>(doc.at("runs"), "evolution document: runs") / static_cast<std::int64_t>(history.size());
    std::vector<storage::ConvergencePoint> points;
    for (const auto& g : history) {
      const int generation = checked_json_integer<int>(g.at("generation"), "evolution document: generation");
      points.push_back({generation, generation * per_generation, g.at("best_mean").get<double>(), 0});
    }
    return points;
  }

  nlohmann::json document(const std::filesystem::path& folder) const override {
    try {  // read on its own by a server that shows the design: no link planted at its name followed
      return nlohmann::json::parse(read_folder_file(folder, kDocumentFile, "EvoStick document", kMaxDocumentBytes).text);
    } catch (const FileReadError& e) {
      if (e.problem == FileProblem::Missing)
        throw std::runtime_error("the EvoStick design in " + folder.string() + " has no " + kDocumentFile);
      throw;
    }
  }

  std::string describe(const storage::PlannedDesign&) const override { return std::string(info().title); }
  bool runs_on_cluster() const override { return false; }
};

}  // namespace

const DesignMethod& evostick_method() {
  static const EvoStick method;
  return method;
}

}  // namespace sd::app
