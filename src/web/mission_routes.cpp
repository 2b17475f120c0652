// The missions a user can run: described and drawn; a project's own mission files, uploaded.
#include "app/documents.hpp"
#include "app/project_missions.hpp"
#include "missions/catalogue.hpp"
#include "missions/svg.hpp"
#include "web/http_io.hpp"
#include "web/mission_access.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_mission_routes(Routes& routes) {
  routes.get("/api/missions", [](Call& call) {
    nlohmann::json list = nlohmann::json::array();
    for (const MissionSummary& m : list_missions()) list.push_back(app::mission_document(load_mission(m.name)));
    for (const std::string& file : project_mission_files(call.home, call.user)) {
      try {
        nlohmann::json doc = app::mission_document(load_user_mission(call.home, call.user, file));
        doc["name"] = file;  // what POST /api/runs takes
        list.push_back(std::move(doc));
      } catch (const std::exception&) {
        // A project whose mission file was since removed or broken: not runnable, not listed.
      }
    }
    return list;
  });

  // A project's own mission files: uploaded or written in the page's mission editor.
  const std::string project = std::string("/api/projects/") + kNamePattern;
  routes.get(project + "/missions", [](Call& call) {
    nlohmann::json list = nlohmann::json::array();
    for (const app::ProjectMission& m : app::list_project_missions(call.home, call.user, call.match(1)))
      list.push_back({{"name", m.name}, {"file", m.file.string()}});
    return list;
  });

  routes.post(project + "/missions", [](Call& call) {
    const app::ProjectMission saved = app::save_project_mission(call.home, call.user, call.match(1),
                                                                text_field(call.body, "name"), text_field(call.body, "text"));
    nlohmann::json doc = app::mission_document(load_user_mission(call.home, call.user, saved.file.string()));
    doc["name"] = saved.file.string();  // what POST /api/projects and /api/runs take
    doc["file_name"] = saved.name;
    return doc;
  });

  // The mission editor's live drawing: checked as an upload is, stored nowhere.
  routes.post(project + "/missions/preview", [](Call& call) -> nlohmann::json {
    const Mission mission = app::check_project_mission(call.home, call.user, call.match(1), text_field(call.body, "name"),
                                                       text_field(call.body, "text"));
    return {{"svg", mission_svg(mission)}, {"mission", app::mission_document(mission)}};
  });

  // A mission's file as written (comments and all): what the mission editor starts from.
  routes.get("/api/missions/text", [](Call& call) -> nlohmann::json {
    const Mission mission = load_user_mission(call.home, call.user, call.request.get_param_value("name"));
    return {{"name", mission.name}, {"text", mission.document}};
  });

  routes.get_raw("/api/missions/svg", [](Call& call) {
    const Mission mission = load_user_mission(call.home, call.user, call.request.get_param_value("name"));
    call.response.set_content(mission_svg(mission), "image/svg+xml");
  });
}

}  // namespace sd::web
