// A SwarmDesign home read from Python as the signed-in user sees it (the session that
// `swarmdesign sign-in` left): projects, their designs (rows and folders), experiments' progress
// and reports, the documents `--json` prints. Nothing here starts, stops or deletes anything.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/accounts.hpp"
#include "app/documents.hpp"
#include "app/cluster_experiments.hpp"
#include "app/experiment_job.hpp"
#include "app/experiment_report.hpp"
#include "app/home.hpp"
#include "app/projects.hpp"
#include "python/bindings.hpp"
#include "python/json_objects.hpp"
#include "storage/designs.hpp"

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

py::object designs(const std::optional<std::string>& home_folder, const std::optional<std::string>& project) {
  auto home = open_home(home_folder);
  const storage::User user = app::signed_in_user(*home);
  const storage::Project p = app::project_or_active(*home, user, project);
  py::list out;
  for (const storage::Design& d : storage::Designs(home->workspace(), p).list()) out.append(to_python(app::design_row_document(d)));
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

py::object experiment_report(const std::string& experiment, const std::optional<std::string>& home_folder,
                             const std::optional<std::string>& project) {
  auto home = open_home(home_folder);
  return to_python(app::experiment_report_document(*home, app::signed_in_user(*home), experiment, project));
}

}  // namespace

void bind_accounts(py::module_& m) {
  m.def("account_projects", &projects, py::arg("home") = py::none(), "The signed-in user's projects (`projects --json`).");
  m.def("account_designs", &designs, py::arg("home") = py::none(), py::arg("project") = py::none(),
        "A project's designs, one row each (the active project when none is named).");
  m.def("account_experiments", &experiments, py::arg("home") = py::none(), py::arg("project") = py::none(),
        "A project's experiments and how far each is.");
  m.def("account_collect", &collect, py::arg("home") = py::none(), py::arg("project") = py::none(),
        py::arg("threads") = 0u, "Brings a cluster project's finished experiment designs home (`collect --json`).");
  m.def("experiment_report", &experiment_report, py::arg("experiment"), py::arg("home") = py::none(),
        py::arg("project") = py::none(), "An experiment's report document, as `report --json` computes it.");
}

}  // namespace sd::python
