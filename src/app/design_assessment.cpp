#include "app/design_assessment.hpp"

#include <mutex>
#include <stdexcept>

#include "app/assess_job.hpp"
#include "app/documents/reality.hpp"
#include "app/design_best.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/pseudo_realities.hpp"
#include "control/config_string.hpp"
#include "core/bounded_file.hpp"
#include "core/durable_file.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"

namespace sd::app {

namespace {

/// One writer at a time in this process: the durable write's temporary is named by the pid.
std::mutex& write_mutex() {
  static std::mutex m;
  return m;
}

/// A request's field, InvalidRequest naming it in one line.
template <class Read>
auto field(const char* name, Read&& read) {
  try {
    return read();
  } catch (const InvalidRequest& e) {
    throw InvalidRequest(std::string(name) + ": " + e.what());
  } catch (const NotFound& e) {
    throw InvalidRequest(std::string(name) + ": " + e.what());
  }
}

storage::Design project_design(Home& home, const storage::User& user, const std::string& project, std::int64_t id) {
  const storage::Project p = storage::Projects(home.workspace(), user).get(project);
  return storage::Designs(home.workspace(), p).get(id);
}

}  // namespace

std::filesystem::path design_assessment_file(const std::filesystem::path& folder) { return folder / "assessment.json"; }

nlohmann::json assess_design_folder(const std::filesystem::path& folder, const Mission& mission,
                                    const ControlSoftware& software, const std::string& label,
                                    const DesignAssessmentRequest& request, const FileScope& scope) {
  const NamedPseudoReality named = field("pseudo_reality", [&] { return load_requested_pseudo_reality(request.pseudo_reality, scope); });
  const std::vector<std::uint64_t> samples = field("samples", [&] { return parse_sample_range(request.samples); });
  const std::vector<std::uint64_t> seeds = field("seeds", [&] { return parse_seed_range(request.seeds); });
  const auto runs = static_cast<std::int64_t>(seeds.size()) * (1 + static_cast<std::int64_t>(samples.size()));
  if (runs > kMaxDesignAssessmentRuns)
    throw InvalidRequest("samples: " + std::to_string(seeds.size()) + " seeds x (1 + " + std::to_string(samples.size()) +
                         " samples) = " + std::to_string(runs) + " runs, more than the " +
                         std::to_string(kMaxDesignAssessmentRuns) + " an assessment may ask for");
  AssessRequest assess_request;
  assess_request.software = {{label, software}};
  assess_request.spec = named.spec;
  assess_request.spec_reference = named.reference;
  assess_request.samples = samples;
  assess_request.seeds = seeds;
  assess_request.threads = request.threads;
  nlohmann::json document = assessment_document(assess(mission, assess_request));
  document["request"] = {{"pseudo_reality", request.pseudo_reality}, {"samples", request.samples}, {"seeds", request.seeds}};
  const std::lock_guard lock(write_mutex());
  replace_file_durably(design_assessment_file(folder), document.dump(1) + "\n", 0644, Umask::Applies);
  return document;
}

std::optional<nlohmann::json> read_design_assessment(const std::filesystem::path& folder) {
  const auto file = design_assessment_file(folder);
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec))) return std::nullopt;
  // The server reads this file on its own: a link planted at its name is not served.
  try {
    return nlohmann::json::parse(
        read_folder_file(folder, file.filename().string(), "assessment file", std::size_t{64} << 20).text);
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error("the design's assessment.json cannot be read: it is not JSON");
  } catch (const FileReadError& e) {
    throw std::runtime_error(e.problem == FileProblem::Outside ? "the design's assessment.json is a link; it is not read"
                                                                : "the design's assessment.json cannot be read");
  }
}

nlohmann::json assess_project_design(Home& home, const storage::User& user, const std::string& project,
                                     std::int64_t design, const DesignAssessmentRequest& request,
                                     const FileScope& scope) {
  // The design's best on its own mission: the rule /test, compare and export follow too.
  const DesignBest best = design_best(home, user, project, design, scope);
  return assess_design_folder(best.design.folder, best.mission, best.software, "design " + std::to_string(design) + " best",
                              request, scope);
}

nlohmann::json project_design_assessment(Home& home, const storage::User& user, const std::string& project,
                                         std::int64_t design) {
  const storage::Design d = project_design(home, user, project, design);
  auto document = read_design_assessment(d.folder);
  if (!document) throw NotFound("design " + std::to_string(design) + " has not been assessed in a pseudo-reality yet");
  return *document;
}

}  // namespace sd::app
