// The editor's two conversions, both through the CLI's one parser: a configuration string to
// the drawing model, and a drawing back to its canonical string.
#include "app/control_software_document.hpp"
#include "app/errors.hpp"
#include "control/config_string.hpp"
#include "control/describe.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_software_routes(Routes& routes) {
  routes.get("/api/catalogue", [](Call&) { return app::catalogue_document(); });

  routes.post("/api/parse", [](Call& call) -> nlohmann::json {
    const std::string text = text_field(call.body, "text");
    ControlSoftware software;
    try {
      software = parse_control_software(text);
    } catch (const ConfigError& e) {
      call.response.status = 400;
      return {{"error", e.what()}, {"token", app::token_named_in(e.what())}};
    }
    return {{"software", app::software_document(software)},
            {"text", to_config_string(software)},
            {"description", describe(software)}};
  });

  routes.post("/api/print", [](Call& call) -> nlohmann::json {
    if (!call.body.contains("software")) throw app::InvalidRequest("software is missing");
    const ControlSoftware software = app::software_from_document(call.body["software"]);
    return {{"text", to_config_string(software)}, {"software", app::software_document(software)}};
  });
}

}  // namespace sd::web
