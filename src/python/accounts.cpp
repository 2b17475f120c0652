// A SwarmDesign home read from Python as the signed-in user sees it (the session that
// `swarmdesign sign-in` left): projects, their designs (rows and folders), experiments' progress
// and reports, the documents `--json` prints; experiments planned, run (in this process, or for a
// cluster project as a Slurm array) and stopped through the backend the CLI and the page use.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "app/accounts.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/cancel_token.hpp"
#include "app/cluster_experiments.hpp"
#include "app/experiment_backends.hpp"
#include "app/experiment_job.hpp"
#include "app/experiment_report.hpp"
#include "app/export_argos.hpp"
#include "app/home.hpp"
#include "app/projects.hpp"
#include "app/protocol_requests.hpp"
#include "app/quotas.hpp"
#include "app/test_design.hpp"
#include "python/bindings.hpp"
#include "python/interruptible.hpp"
#include "python/json_objects.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

/// The home opened for each request, as every CLI command opens it.
std::unique_ptr<app::Home> open_home(const std::optional<std::string>& folder) {
  return folder ? std::make_unique<app::Home>(*folder) : std::make_unique<app::Home>();
}

py::object projects(const std::optional<std::string>& home_folder) {
  auto home = open_home(home_folder);
  return to_python(app::projects_document(app::list_projects(*home, app::signed_in_user(*home))));
}

py::object quota(const std::optional<std::string>& home_folder) {
  auto home = open_home(home_folder);
  return to_python(app::quota_document(app::quota_use(*home, app::signed_in_user(*home))));
}

py::object designs(const std::optional<std::string>& home_folder, const std::optional<std::string>& project) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  py::list out;
  for (const storage::Design& d : app::list_designs(*home, user, project)) out.append(to_python(app::design_row_document(d)));
  return out;
}

py::object experiments(const std::optional<std::string>& home_folder, const std::optional<std::string>& project) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  return to_python(app::experiments_document(app::experiments_progress(*home, user, project)));
}

py::object collect(const std::optional<std::string>& home_folder, const std::optional<std::string>& project, unsigned threads) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  const storage::Project p = app::project_or_active(*home, user, project);
  const app::ClusterCollection c = [&] {
    py::gil_scoped_release free;  // assessing is simulation
    return app::collect_cluster_experiments(*home, user, p.name, threads);
  }();
  return to_python(app::collection_document(p.name, c, app::experiments_progress(*home, user, p.name)));
}

// A design's best on fresh seeds, two designs compared, a design for ARGoS: the services the
// CLI's test-design, compare-designs and export-argos and the web's /test, /compare and /argos
// call (app/test_design, app/export_argos), so the documents are the same.
py::object test_design(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                       std::optional<std::int64_t> design, const std::optional<ControlSoftware>& software,
                       const std::string& seeds, int threads) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  app::TestDesignRequest request{project, design, software, seeds, threads, {}};
  const nlohmann::json doc = [&] {
    py::gil_scoped_release free;
    return app::test_design(*home, user, request);
  }();
  return to_python(doc);
}

py::object compare_designs(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                           std::int64_t a, std::int64_t b, const std::string& seeds, int threads) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  app::CompareDesignsRequest request{project, a, b, seeds, threads, {}};
  const nlohmann::json doc = [&] {
    py::gil_scoped_release free;
    return app::compare_designs(*home, user, request);
  }();
  return to_python(doc);
}

py::object argos_files(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                       std::optional<std::int64_t> design, const std::string& pseudo_reality, const std::string& sample) {
  auto home = open_home(home_folder);
  app::ArgosFilesRequest request{project, design, std::nullopt, pseudo_reality, sample};
  return to_python(app::argos_files(*home, app::signed_in_user(*home), request));
}

// An experiment's request is the web's JSON body, as text (app::protocol_request_from_json):
// Python builds it from its keywords, so the three front ends fill one request.
app::ProtocolRequest protocol_request(const std::string& request_json) {
  const nlohmann::json body = nlohmann::json::parse(request_json, nullptr, false);
  if (body.is_discarded()) throw app::InvalidRequest("the experiment request is not JSON");
  return app::protocol_request_from_json(body);
}

py::object plan_experiment(const std::string& request_json, std::optional<unsigned> estimate_threads) {
  const app::ProtocolRequest request = protocol_request(request_json);
  const nlohmann::json doc = [&] {
    py::gil_scoped_release free;  // the estimate simulates
    return app::estimated_plan_document(app::plan_with_estimate(request, app::FileScope::local(), estimate_threads));
  }();
  return to_python(doc);
}

/// Hands the experiment's progress from its thread to the Python thread that polls.
class ExperimentRelay final : public app::ExperimentObserver {
 public:
  void design_started(const storage::ExperimentDesign& d, int index, int total) override {
    const std::lock_guard lock(mutex_);
    now_ = {{"design", index}, {"designs", total}, {"mission", app::mission_label(d.plan.mission)},
            {"condition", d.plan.condition}, {"replicate", d.plan.replicate}, {"stage", "designing"}};
    fresh_ = true;
  }
  void design_progress(std::int64_t runs_used, std::int64_t budget, double best_score) override {
    const std::lock_guard lock(mutex_);
    now_["runs_used"] = runs_used;
    now_["budget"] = budget;
    now_["best_score"] = best_score;
    fresh_ = true;
  }
  void assessing(std::size_t done, std::size_t all) override {
    const std::lock_guard lock(mutex_);
    now_["stage"] = "assessing";
    now_["assessed"] = done;
    now_["to_assess"] = all;
    fresh_ = true;
  }
  std::optional<nlohmann::json> take() {
    const std::lock_guard lock(mutex_);
    if (!fresh_) return std::nullopt;
    fresh_ = false;
    return now_;
  }

 private:
  std::mutex mutex_;
  nlohmann::json now_ = nlohmann::json::object();
  bool fresh_ = false;
};

// Started (or resumed) where the project's experiments run: this process, or a Slurm array for
// a cluster project (app::launch_experiment, as `swarmdesign experiment`). Here it runs to its
// end; Ctrl-C stops it between race steps, and the same call resumes it.
py::object run_experiment(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                          const std::string& request_json, unsigned threads, const py::object& progress) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  app::LaunchedExperiment launched =
      app::launch_experiment(*home, user, {protocol_request(request_json), project, app::FileScope::local(), {}, threads});
  if (launched.where == app::ExperimentWhere::this_process && !launched.started.already_finished) {
    ExperimentRelay relay;
    app::CancelToken token;
    run_interruptibly(
        [&] { app::run_experiment(launched.started, {.threads = threads, .evaluator = nullptr, .observer = &relay, .cancel = &token}); },
        [&] { token.cancel(); },
        [&] {
          if (auto now = relay.take(); now && !progress.is_none()) progress(to_python(*now));
        });
  }
  const std::string& name = launched.started.experiment.name;
  for (const nlohmann::json& row : app::experiments_document(app::experiments_progress(*home, user, launched.started.project.name)))
    if (row.at("name") == name) return to_python(app::launched_experiment_document(launched, row));
  throw app::NotFound("experiment " + name + " vanished");
}

py::object stop_experiment(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                           const std::string& name) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  const storage::Project p = app::project_or_active(*home, user, project);
  return to_python(nlohmann::json{{"stopping", app::stop_experiment(*home, user, p.name, name)}});
}

py::object experiment_report(const std::string& experiment, const std::optional<std::string>& home_folder,
                             const std::optional<std::string>& project) {
  auto home = open_home(home_folder);
  return to_python(app::experiment_report_document(*home, app::signed_in_user(*home), experiment, project));
}

// Projects made, configured and deleted as `new-project`, `set-mission`, `set-budget` and
// `delete-project` make them (app/projects): the same checks, before anything is written.
py::object new_project(const std::optional<std::string>& home_folder, const std::string& name, const std::string& mission,
                       const std::string& budget) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  return to_python(app::project_document(
      app::create_configured_project(*home, user, name, mission, budget, app::FileScope::local())));
}

py::object configure_project(const std::optional<std::string>& home_folder, const std::string& name,
                             const std::optional<std::string>& mission, const std::optional<std::string>& budget) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  storage::Project project = app::select_project(*home, user, name);
  if (mission) project = app::set_mission(*home, user, *mission);
  if (budget) project = app::set_budget(*home, user, *budget);
  return to_python(app::project_document(project));
}

void delete_project(const std::optional<std::string>& home_folder, const std::string& name, const std::string& confirmation) {
  auto home = open_home(home_folder);
  app::delete_project(*home, app::signed_in_user(*home), name, confirmation);
}

}  // namespace

void bind_accounts(py::module_& m) {
  m.def("account_new_project", &new_project, py::arg("home"), py::arg("name"), py::arg("mission"), py::arg("budget"),
        "A project with its mission and budget, made active (`new-project`, `set-mission`, `set-budget`).");
  m.def("account_configure_project", &configure_project, py::arg("home"), py::arg("name"), py::arg("mission"),
        py::arg("budget"), "A project's mission and/or budget set, the project made active (`set-mission`, `set-budget`).");
  m.def("account_delete_project", &delete_project, py::arg("home"), py::arg("name"), py::arg("confirmation"),
        "Deletes a project and everything in it once confirmation repeats its name (`delete-project`).");
  m.def("account_projects", &projects, py::arg("home") = py::none(), "The signed-in user's projects (`projects --json`).");
  m.def("account_quota", &quota, py::arg("home") = py::none(), "What the account uses of its quotas (`quota --json`).");
  m.def("account_designs", &designs, py::arg("home") = py::none(), py::arg("project") = py::none(),
        "A project's designs, one row each (the active project when none is named).");
  m.def("account_experiments", &experiments, py::arg("home") = py::none(), py::arg("project") = py::none(),
        "A project's experiments and how far each is.");
  m.def("account_collect", &collect, py::arg("home") = py::none(), py::arg("project") = py::none(),
        py::arg("threads") = 0u, "Brings a cluster project's finished experiment designs home (`collect --json`).");
  m.def("account_test_design", &test_design, py::arg("home"), py::arg("project"), py::arg("design"), py::arg("software"),
        py::arg("seeds"), py::arg("threads"), "A design's best (or software) on fresh seeds (`test-design --json`).");
  m.def("account_compare_designs", &compare_designs, py::arg("home"), py::arg("project"), py::arg("a"), py::arg("b"),
        py::arg("seeds"), py::arg("threads"), "Two designs' bests on the same seeds (`compare-designs --json`).");
  m.def("account_argos_files", &argos_files, py::arg("home"), py::arg("project"), py::arg("design"),
        py::arg("pseudo_reality"), py::arg("sample"), "A design for ARGoS3-AutoMoDe (`export-argos --json`).");
  m.def("account_plan_experiment", &plan_experiment, py::arg("request"), py::arg("estimate_threads"),
        "An experiment's plan (`experiment --dry-run --json`); with estimate_threads, its time here.");
  m.def("account_run_experiment", &run_experiment, py::arg("home"), py::arg("project"), py::arg("request"),
        py::arg("threads"), py::arg("progress"), "Starts or resumes an experiment where the project runs them.");
  m.def("account_stop_experiment", &stop_experiment, py::arg("home"), py::arg("project"), py::arg("name"),
        "Stops an experiment through whoever runs it (`POST .../experiments/NAME/stop`).");
  m.def("experiment_report", &experiment_report, py::arg("experiment"), py::arg("home") = py::none(),
        py::arg("project") = py::none(), "An experiment's report document, as `report --json` computes it.");
}

}  // namespace sd::python
