// The design monitor: a user's projects, their designs (started and stopped through their
// backend, app/design_backends.hpp, whoever runs them), and control software saved in a project.
#include <charconv>

#include "app/design_assessment.hpp"
#include "app/design_backends.hpp"
#include "app/design_spaces.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/experiment_job.hpp"
#include "app/export_argos.hpp"
#include "app/inputs.hpp"
#include "app/project_design.hpp"
#include "app/test_design.hpp"
#include "app/projects.hpp"
#include "app/saved_software.hpp"
#include "control/config_string.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

using nlohmann::json;


app::ProjectDesignRequest design_request(const json& body) {
  app::ProjectDesignRequest request;
  const std::string architectures = body.contains("architectures") ? text_field(body, "architectures") : "";
  const std::string flavours = body.contains("flavours") ? text_field(body, "flavours") : "";
  request.space = app::design_space_request(architectures, flavours);
  request.space_given = !architectures.empty() || !flavours.empty();
  if (body.contains("seed") && !body.at("seed").is_null()) request.seed = app::parse_seed(text_field(body, "seed"));
  if (body.contains("fresh") && !body.at("fresh").is_null()) {
    // body.value() would throw json's type_error, answered as a 500.
    if (!body.at("fresh").is_boolean()) throw app::InvalidRequest("fresh must be true or false");
    request.fresh = body.at("fresh").get<bool>();
  }
  // A robust design (run-design --pseudo-reality): a shipped name or a file of the user's projects.
  if (const char* key = alias_or(body, "pseudo_reality", "pseudo_realities"); body.contains(key) && !body.at(key).is_null())
    request.pseudo_reality = text_field(body, key);
  if (body.contains("pseudo_reality_samples") && !body.at("pseudo_reality_samples").is_null()) {
    if (request.pseudo_reality.empty()) throw app::InvalidRequest("pseudo_reality_samples needs pseudo_reality");
    request.pseudo_reality_samples = text_field(body, "pseudo_reality_samples");
  }
  // The optimiser (run-design --method): automode's Iterated F-Race when absent.
  if (body.contains("method") && !body.at("method").is_null()) {
    request.method = &app::search_method(text_field(body, "method"));
    request.space_given = true;
  }
  return request;
}

/// A design's number as a route or query gives it.
std::int64_t design_number(const std::string& text) {
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size() || id <= 0)
    throw app::InvalidRequest("design '" + text + "' must be a design's number");
  return id;
}

/// The body's "design": a design's number, or absent/null for none.
std::optional<std::int64_t> optional_design(const json& body) {
  if (!body.contains("design") || body.at("design").is_null()) return std::nullopt;
  if (!body.at("design").is_number_integer()) throw app::InvalidRequest("design must be a design's number");
  return body.at("design").get<std::int64_t>();
}

}  // namespace

void add_project_routes(Routes& routes) {
  const std::string project = std::string("/api/projects/") + kNamePattern;

  routes.get("/api/projects", [](Call& call) {
    return app::projects_document(app::list_projects(call.home, call.user))["projects"];
  });

  routes.post("/api/projects", [](Call& call) {
    return app::project_document(app::create_configured_project(call.home, call.user, text_field(call.body, "name"),
                                                                text_field(call.body, "mission"),
                                                                text_field(call.body, "budget"),
                                                                app::FileScope::own_projects(call.home, call.user)));
  });

  // set-mission from the page: the CLI's service and checks, under the server's file rule (a
  // catalogue name or a mission file of the user's own projects).
  routes.post(project + "/mission", [](Call& call) {
    return app::project_document(app::set_project_mission(call.home, call.user, call.match(1),
                                                          text_field(call.body, "mission"),
                                                          app::FileScope::own_projects(call.home, call.user)));
  });

  routes.get(project + "/status", [](Call& call) {
    std::optional<std::int64_t> design;
    if (call.request.has_param("design")) design = design_number(call.request.get_param_value("design"));
    const auto detail = status_detail(call.request);
    const app::DesignStatus status = app::design_status(call.home, call.user, detail, call.match(1), design);
    json doc = app::status_document(status, detail);
    doc["running_here"] = call.context.designs.running_here(status.project.id);
    doc["budget"] = status.project.budget ? json(*status.project.budget) : json();
    const auto problem = app::mission_problem(status.project);
    doc["mission_problem"] = problem ? json(*problem) : json();
    const auto experiments = app::experiments_progress(call.home, call.user, call.match(1));
    doc["experiments"] = app::experiments_document(experiments);
    for (std::size_t i = 0; i < experiments.size(); ++i)
      doc["experiments"][i]["running_here"] = call.context.experiments.running_here(experiments[i].experiment.id);
    follow_running(call, call.match(1), experiments);
    return doc;
  });

  routes.get(project + "/designs", [](Call& call) {
    json list = json::array();
    const auto designs = app::list_designs(call.home, call.user, call.match(1));
    for (auto it = designs.rbegin(); it != designs.rend(); ++it) list.push_back(app::design_row_document(*it));
    return list;
  });

  routes.post(project + "/designs", [](Call& call) {
    app::DesignLaunch launch;
    launch.design = design_request(call.body);
    launch.design.project = call.match(1);
    return app::design_row_document(app::start_design(call.home, call.user, launch, &call.context.designs).design);
  });

  // Deleting asks for the project's name again, as the page's confirmation does: a script
  // cannot delete a project by a mistaken route alone.
  routes.post(project + "/delete", [](Call& call) -> json {
    app::delete_project(call.home, call.user, call.match(1), call.body.contains("confirm") ? text_field(call.body, "confirm") : "");
    return {{"deleted", call.match(1)}};
  });

  routes.post(project + "/designs/([0-9]{1,18})/delete", [](Call& call) -> json {
    const std::int64_t id = design_number(call.match(2));
    app::delete_design(call.home, call.user, call.match(1), id);
    return {{"deleted", id}};
  });

  // Whoever runs it: this server's thread, a CLI process of this machine, a Slurm job.
  routes.post(project + "/designs/stop", [](Call& call) -> json {
    app::stop_design(call.home, call.user, call.match(1), &call.context.designs);
    return {{"stopping", true}};
  });

  // test-design from the page: a design's best (or the control software sent) on fresh seeds,
  // scored as the CLI scores it.
  routes.post(project + "/test", [](Call& call) {
    app::TestDesignRequest request;
    request.project = call.match(1);
    request.design = optional_design(call.body);
    if (call.body.contains("seeds")) request.seeds = text_field(call.body, "seeds");
    if (call.body.contains("text") && !call.body.at("text").is_null())
      request.software = parse_control_software(text_field(call.body, "text"));
    return app::test_design(call.home, call.user, request, app::FileScope::own_projects(call.home, call.user),
                            app::TestLimits::page());
  });

  // A design's best across the reality gap (issue #46): assessed in a pseudo-reality (a shipped
  // one or the user's own file) on seeds 1-10 of the design model and of samples 1-20 unless
  // asked otherwise, kept as assessment.json in the design's folder (app/design_assessment).
  routes.post(project + "/designs/([0-9]{1,18})/assessment", [](Call& call) -> json {
    app::DesignAssessmentRequest request;
    request.pseudo_reality = text_field(call.body, alias_or(call.body, "pseudo_reality", "spec"));
    if (call.body.contains("samples") && !call.body.at("samples").is_null()) request.samples = text_field(call.body, "samples");
    if (call.body.contains("seeds") && !call.body.at("seeds").is_null()) request.seeds = text_field(call.body, "seeds");
    return app::assess_project_design(call.home, call.user, call.match(1), design_number(call.match(2)), request,
                                      app::FileScope::own_projects(call.home, call.user));
  });
  routes.get(project + "/designs/([0-9]{1,18})/assessment", [](Call& call) -> json {
    return app::project_design_assessment(call.home, call.user, call.match(1), design_number(call.match(2)));
  });

  // Two designs' bests on the same fresh seeds, with the paired test an experiment's report uses.
  routes.post(project + "/compare", [](Call& call) -> json {
    const json& designs = call.body.contains("designs") ? call.body.at("designs") : json();
    if (!designs.is_array() || designs.size() != 2 || !designs[0].is_number_integer() || !designs[1].is_number_integer())
      throw app::InvalidRequest("designs must be two designs' numbers");
    app::CompareDesignsRequest request;
    request.project = call.match(1);
    request.a = designs[0].get<std::int64_t>();
    request.b = designs[1].get<std::int64_t>();
    if (call.body.contains("seeds")) request.seeds = text_field(call.body, "seeds");
    return app::compare_designs(call.home, call.user, request, app::FileScope::own_projects(call.home, call.user),
                                app::TestLimits::page());
  });

  // A design's best for ARGoS3-AutoMoDe, as `export --argos` and `mission export-argos` give it:
  // the project's mission as an experiment file and the one-digit string its code base reads.
  // The control software sent (the best the page shows), else design ID's best, as for /test.
  routes.post(project + "/argos", [](Call& call) -> json {
    app::ArgosFilesRequest request;
    request.project = call.match(1);
    request.design = optional_design(call.body);
    if (call.body.contains("text") && !call.body.at("text").is_null())
      request.software = parse_control_software(text_field(call.body, "text"));
    if (call.body.contains("pseudo_reality") && !call.body.at("pseudo_reality").is_null())
      request.pseudo_reality = text_field(call.body, "pseudo_reality");
    if (call.body.contains("sample") && !call.body.at("sample").is_null()) request.sample = text_field(call.body, "sample");
    return app::argos_files(call.home, call.user, request, app::FileScope::own_projects(call.home, call.user));
  });

  routes.get(project + "/software", [](Call& call) {
    json list = json::array();
    for (const auto& s : app::list_saved_software(call.home, call.user, call.match(1)))
      list.push_back({{"name", s.name}, {"text", s.text}});
    return list;
  });

  routes.post(project + "/software/([A-Za-z0-9][A-Za-z0-9._-]{0,63})/delete", [](Call& call) -> json {
    app::delete_saved_software(call.home, call.user, call.match(1), call.match(2));
    return {{"deleted", call.match(2)}};
  });

  routes.post(project + "/software", [](Call& call) -> json {
    const app::SavedSoftware s = app::save_software(call.home, call.user, call.match(1), text_field(call.body, "name"),
                                                    text_field(call.body, "text"));
    return {{"name", s.name}, {"text", s.text}};
  });
}

}  // namespace sd::web
