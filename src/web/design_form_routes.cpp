// What the page's start-a-design form needs besides starting: the design space a choice of
// architectures and flavours resolves to, with the least budget Iterated F-Race accepts for it,
// and the project's budget set from the form (as set-budget).
#include "app/design_job.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/projects.hpp"
#include "design/design_space.hpp"
#include "modules/catalogue.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

using nlohmann::json;

design::DesignSpaceChoice choice_of(const std::string& architectures, const std::string& flavours) {
  try {
    return design::resolve_design_space(design::request_from_text(architectures, flavours));
  } catch (const std::invalid_argument& e) {
    throw app::InvalidRequest(e.what());
  }
}

}  // namespace

void add_design_form_routes(Routes& routes) {
  routes.get("/api/design-space", [](Call& call) -> json {
    const design::DesignSpaceChoice choice =
        choice_of(call.request.get_param_value("architectures"), call.request.get_param_value("flavours"));
    json flavours = json::array();
    for (const Flavour f : choice.flavours) flavours.push_back(std::string(flavour_name(f)));
    return {{"architectures", choice.architectures},
            {"flavours", flavours},
            {"notes", choice.notes},
            {"minimum_budget", app::minimum_design_budget(design::build_design_space(choice))}};
  });

  routes.post(std::string("/api/projects/") + kNamePattern + "/budget", [](Call& call) -> json {
    app::select_project(call.home, call.user, call.match(1));
    return app::project_document(app::set_budget(call.home, call.user, text_field(call.body, "budget")));
  });
}

}  // namespace sd::web
