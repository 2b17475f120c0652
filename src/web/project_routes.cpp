// The design monitor: a user's projects, their designs (started and stopped here or followed
// while the CLI runs them), and control software saved in a project.
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/project_design.hpp"
#include "app/projects.hpp"
#include "control/config_string.hpp"
#include "core/durable_file.hpp"
#include "design/design_space.hpp"
#include "missions/catalogue.hpp"
#include "storage/designs.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

using nlohmann::json;

std::string text_of(const json& body, const char* key) {
  if (!body.contains(key)) throw app::InvalidRequest(std::string(key) + " is missing");
  const json& v = body.at(key);
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer()) return v.dump();
  throw app::InvalidRequest(std::string(key) + " must be text or a whole number");
}

storage::Project project_of(Call& call) {
  return storage::Projects(call.home.workspace(), call.user).get(call.match(1));
}

app::ProjectDesignRequest design_request(const json& body) {
  app::ProjectDesignRequest request;
  const std::string architectures = body.contains("architectures") ? text_of(body, "architectures") : "";
  const std::string flavours = body.contains("flavours") ? text_of(body, "flavours") : "";
  try {
    request.space = design::request_from_text(architectures, flavours);
  } catch (const std::invalid_argument& e) {
    throw app::InvalidRequest(e.what());
  }
  request.space_given = !architectures.empty() || !flavours.empty();
  if (body.contains("seed") && !body.at("seed").is_null()) request.seed = app::parse_seed(text_of(body, "seed"));
  request.fresh = body.value("fresh", false);
  return request;
}

/// Saved control software: <project>/software/<name>.txt, one canonical string each.
std::filesystem::path software_folder(const storage::Project& project) { return project.folder / "software"; }

std::string software_name(const json& body) {
  static const std::regex rule("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
  const std::string name = text_of(body, "name");
  if (!std::regex_match(name, rule))
    throw app::InvalidRequest("name '" + name + "' must be 1-64 letters, digits, '.', '_' or '-', not starting with '.'");
  return name;
}

}  // namespace

void add_project_routes(Routes& routes) {
  const std::string project = std::string("/api/projects/") + kNamePattern;

  routes.get("/api/projects", [](Call& call) {
    return app::projects_document(app::list_projects(call.home, call.user))["projects"];
  });

  routes.post("/api/projects", [](Call& call) {
    const std::string name = text_of(call.body, "name");
    // Every value is checked before the project exists, so a refusal leaves nothing behind.
    const std::string mission = mission_reference(text_of(call.body, "mission"));
    app::load_requested_mission(mission);
    const std::string budget = text_of(call.body, "budget");
    app::parse_budget(budget);
    app::create_project(call.home, call.user, name, std::nullopt);
    app::select_project(call.home, call.user, name);
    app::set_mission(call.home, call.user, mission);
    return app::project_document(app::set_budget(call.home, call.user, budget));
  });

  routes.get(project + "/status", [](Call& call) {
    const app::DesignStatus status = app::design_status(call.home, call.user, true, call.match(1));
    json doc = app::status_document(status, true);
    doc["running_here"] = call.context.designs.running_here(status.project.id);
    doc["budget"] = status.project.budget ? json(*status.project.budget) : json();
    return doc;
  });

  routes.get(project + "/designs", [](Call& call) {
    json list = json::array();
    auto designs = storage::Designs(call.home.workspace(), project_of(call)).list();
    for (auto it = designs.rbegin(); it != designs.rend(); ++it) list.push_back(app::design_row_document(*it));
    return list;
  });

  routes.post(project + "/designs", [](Call& call) {
    return app::design_row_document(call.context.designs.start(call.user, call.match(1), design_request(call.body)));
  });

  routes.post(project + "/designs/stop", [](Call& call) -> json {
    const storage::Project p = project_of(call);
    if (call.context.designs.stop(p.id)) return {{"stopping", true}};
    const auto latest = storage::Designs(call.home.workspace(), p).latest();
    if (latest && latest->state == storage::DesignState::running)
      throw app::Conflict("design " + std::to_string(latest->id) + " runs in another process (pid " +
                          std::to_string(latest->pid) + "): stop it there");
    throw app::Conflict("no design of " + p.name + " is running");
  });

  routes.get(project + "/software", [](Call& call) {
    json list = json::array();
    const auto folder = software_folder(project_of(call));
    if (!std::filesystem::is_directory(folder)) return list;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".txt") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      std::ifstream in(file);
      std::stringstream text;
      text << in.rdbuf();
      list.push_back({{"name", file.stem().string()}, {"text", text.str()}});
    }
    return list;
  });

  routes.post(project + "/software", [](Call& call) -> json {
    const storage::Project p = project_of(call);
    const std::string name = software_name(call.body);
    const std::string text = to_config_string(parse_control_software(text_of(call.body, "text")));
    std::filesystem::create_directories(software_folder(p));
    replace_file_durably(software_folder(p) / (name + ".txt"), text, 0644, Umask::Applies);
    return {{"name", name}, {"text", text}};
  });
}

}  // namespace sd::web
