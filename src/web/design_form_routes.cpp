// What the page's start-a-design form needs besides starting: the design space a choice of
// architectures and flavours resolves to, with the least budget Iterated F-Race accepts for it,
// and the project's budget set from the form (as set-budget).
#include "app/design_job.hpp"
#include "app/design_spaces.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/projects.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

using nlohmann::json;

void add_design_form_routes(Routes& routes) {
  routes.get("/api/design-space", [](Call& call) -> json {
    return app::design_space_document(call.request.get_param_value("architectures"),
                                      call.request.get_param_value("flavours"), call.request.get_param_value("method"));
  });

  routes.post(std::string("/api/projects/") + kNamePattern + "/budget", [](Call& call) -> json {
    app::select_project(call.home, call.user, call.match(1));
    return app::project_document(app::set_budget(call.home, call.user, text_field(call.body, "budget")));
  });
}

}  // namespace sd::web
