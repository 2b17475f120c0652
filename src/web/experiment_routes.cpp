// A project's experiments: started, stopped and resumed from the page (run on this server's
// threads), their progress (the Designs tab lists them) and their report, the same page
// `swarmdesign report` writes, made afresh from the database at every request.
#include "app/design_backends.hpp"
#include "app/documents/design.hpp"
#include "app/documents/experiments.hpp"
#include "app/errors.hpp"
#include "app/experiment_backends.hpp"
#include "app/experiment_job.hpp"
#include "app/user_files.hpp"
#include "experiments/protocol.hpp"
#include "app/experiment_report.hpp"
#include "app/protocol_requests.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

namespace {

using nlohmann::json;

/// The project's experiments, each saying whether this server runs it.
json experiments_list(Call& call, const std::string& project) {
  const auto progress = app::experiments_progress(call.home, call.user, project);
  json list = app::experiments_document(progress);
  for (std::size_t i = 0; i < progress.size(); ++i)
    list[i]["running_here"] = call.context.experiments.running_here(progress[i].experiment.id);
  follow_running(call, project, progress);
  return list;
}

/// Started where the project's experiments run (app::launch_experiment): this server's thread,
/// or for a cluster project a Slurm job array ("where": "server" or "slurm").
json launched_document(Call& call, const app::ProtocolRequest& protocol) {
  const app::LaunchedExperiment launched = app::launch_experiment(
      call.home, call.user, {protocol, call.match(1), app::FileScope::own_projects(call.home, call.user), {}, 0},
      &call.context.experiments);
  const app::StartedExperiment& started = launched.started;
  for (const json& e : experiments_list(call, started.project.name))
    if (e.at("name") == started.experiment.name)
      return app::launched_experiment_document(launched, e);
  throw app::NotFound("experiment " + started.experiment.name + " vanished");
}

/// An experiment's design as /status shows a design: the one it is making, or design `id`.
json experiment_design_answer(Call& call, std::optional<std::int64_t> id) {
  const auto detail = status_detail(call.request);
  const app::DesignStatus status =
      app::experiment_design_status(call.home, call.user, call.match(1), call.match(2), detail, id);
  json doc = app::status_document(status, detail);
  doc["running_here"] = false;  // the experiment's thread, not a design's: Stop is the experiment's
  doc["budget"] = status.design->budget;
  return doc;
}

}  // namespace

void add_experiment_routes(Routes& routes) {
  const std::string project = std::string("/api/projects/") + kNamePattern;

  // The thesis' protocols, whole, for the page to offer and show.
  routes.get("/api/protocols", [](Call&) {
    json list = json::array();
    for (const std::string& name : experiments::builtin_protocol_names())
      list.push_back({{"name", name}, {"protocol", experiments::to_json(experiments::builtin_protocol(name))}});
    return list;
  });

  routes.get(project + "/experiments", [](Call& call) { return experiments_list(call, call.match(1)); });

  // `swarmdesign experiment` from the page: planned (dry_run: only that; with estimate, also how
// long it would take on this server's threads, measured now), recorded and run where
  // the project's experiments run; the same name and protocol again resumes an interrupted one.
  routes.post(project + "/experiments", [](Call& call) -> json {
    const app::ProtocolRequest request = app::protocol_request_from_json(call.body);
    const auto flag = [&](const char* key) {
      return call.body.contains(key) && call.body.at(key).is_boolean() && call.body.at(key).get<bool>();
    };
    if (flag("dry_run"))
      return app::estimated_plan_document(app::plan_with_estimate(
          request, app::FileScope::own_projects(call.home, call.user), flag("estimate") ? std::optional<unsigned>(0) : std::nullopt));
    return launched_document(call, request);
  });

  // The design an experiment is making (/current), or any design of it made or being made, as
  // the monitor shows a design (`status --complete`).
  routes.get(project + "/experiments/" + kNamePattern + "/current",
             [](Call& call) { return experiment_design_answer(call, std::nullopt); });
  routes.get(project + "/experiments/" + kNamePattern + "/designs/([0-9]{1,18})",
             [](Call& call) { return experiment_design_answer(call, std::stoll(call.match(3))); });

  routes.post(project + "/experiments/" + kNamePattern + "/stop", [](Call& call) -> json {
    return {{"stopping", app::stop_experiment(call.home, call.user, call.match(1), call.match(2), &call.context.experiments)}};
  });

  // An interrupted experiment goes on with the protocol it was started with.
  routes.post(project + "/experiments/" + kNamePattern + "/resume", [](Call& call) -> json {
    app::ProtocolRequest stored;
    stored.text = experiments::to_json(app::stored_protocol(call.home, call.user, call.match(1), call.match(2))).dump();
    return launched_document(call, stored);
  });

  routes.get_raw(project + "/experiments/" + kNamePattern + "/report", [](Call& call) {
    const auto document = app::experiment_report_document(call.home, call.user, call.match(2), call.match(1));
    // The page is self-contained: its script, style and data are inline; it loads nothing.
    call.response.set_header("Content-Security-Policy",
                             "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                             "img-src data: blob:; frame-ancestors 'none'");
    call.response.set_content(app::experiment_report_html(document, call.context.web_root), "text/html; charset=utf-8");
  });

  // The files the page points to ("report.json and the CSV files next to this page"): relative
  // to the page's address they land here, as they do next to report.html in a report folder.
  routes.get_raw(project + "/experiments/" + kNamePattern + "/([a-z_]{1,32}\\.(?:csv|json))", [](Call& call) {
    const auto document = app::experiment_report_document(call.home, call.user, call.match(2), call.match(1));
    const std::string name = call.match(3);
    for (const app::ReportFile& f : app::experiment_report_data_files(document)) {
      if (f.name != name) continue;
      call.response.set_header("Content-Security-Policy", "default-src 'none'; sandbox");
      call.response.set_header("Content-Disposition", "attachment; filename=\"" + call.match(2) + "-" + name + "\"");
      call.response.set_content(f.content, name.ends_with(".json") ? "application/json" : "text/csv; charset=utf-8");
      return;
    }
    throw app::NotFound("the report has no file " + name);
  });
}

}  // namespace sd::web
