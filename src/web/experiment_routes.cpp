// A project's experiments: their progress (the Designs tab lists them) and their report, the
// same page `swarmdesign report` writes, made afresh from the database at every request.
#include "app/experiment_job.hpp"
#include "app/errors.hpp"
#include "app/experiment_report.hpp"
#include "web/http_io.hpp"
#include "web/routes.hpp"

namespace sd::web {

void add_experiment_routes(Routes& routes) {
  const std::string project = std::string("/api/projects/") + kNamePattern;

  routes.get(project + "/experiments", [](Call& call) {
    return app::experiments_document(app::experiments_progress(call.home, call.user, call.match(1)));
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
