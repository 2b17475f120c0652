// Designs from Python: Iterated F-Race run in-process by the job the CLI's `design` runs
// (app/design_job.hpp: prepared, checkpointed into DIR/design.db, resumable), and any design
// folder read back (its progress, race log and convergence, as `design-status --json` and
// `status --json` give them).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/cancel_token.hpp"
#include "app/design_job.hpp"
#include "app/design_method.hpp"
#include "app/design_spaces.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "missions/catalogue.hpp"
#include "python/bindings.hpp"
#include "python/interruptible.hpp"
#include "python/json_objects.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

/// Hands each race step's progress from the job's thread to the Python thread that polls.
class ProgressRelay final : public app::DesignObserver {
 public:
  explicit ProgressRelay(bool maximise) : maximise_(maximise) {}
  void progress(const design::Progress& p) override {
    const std::lock_guard lock(mutex_);
    latest_ = app::progress_document(p, maximise_);
  }
  std::optional<nlohmann::json> take() {
    const std::lock_guard lock(mutex_);
    std::optional<nlohmann::json> out = std::move(latest_);
    latest_.reset();
    return out;
  }

 private:
  bool maximise_;
  std::mutex mutex_;
  std::optional<nlohmann::json> latest_;
};

py::object run_prepared(app::PreparedDesign& prepared, unsigned threads, const py::object& progress) {
  constexpr unsigned kMaxThreads = 1024;  // as evaluate: each worker is a thread and a simulation
  if (threads > kMaxThreads) throw app::InvalidRequest("threads: at most " + std::to_string(kMaxThreads));
  ProgressRelay relay(prepared.mission.objective.direction == Direction::Maximize);
  app::CancelToken token;
  app::DesignOutcome outcome;
  run_interruptibly(
      [&] { outcome = app::run_design(prepared, {.threads = threads, .observer = &relay, .cancel = &token}); },
      [&] { token.cancel(); },
      [&] {
        auto latest = relay.take();
        if (latest && !progress.is_none()) progress(to_python(*latest));
      });
  if (!outcome.report) throw std::runtime_error("the design in " + prepared.folder.string() + " stopped before it finished");
  py::dict report = to_python(app::design_report_document(*outcome.report));
  report["notes_from_choice"] = prepared.choice.notes;
  return report;
}

py::object design(const std::string& mission, long long budget, const std::vector<std::string>& architectures,
                  const std::vector<std::string>& flavours, std::uint64_t seed, const std::string& folder, unsigned threads,
                  const py::object& progress, const std::string& pseudo_reality, const std::string& pseudo_reality_samples,
                  const std::string& method) {
  app::NewDesignSettings settings;
  settings.method = &app::search_method(method);
  settings.mission = mission;
  settings.budget = budget;
  settings.space = app::design_space_request(architectures, flavours);
  settings.seed = seed;
  if (!pseudo_reality_samples.empty() && pseudo_reality.empty())
    throw app::InvalidRequest("pseudo_reality_samples needs pseudo_reality");
  settings.pseudo_reality = pseudo_reality;  // a robust design (run-design --pseudo-reality)
  if (!pseudo_reality_samples.empty()) settings.pseudo_reality_samples = pseudo_reality_samples;
  // A folder that holds this design already goes on with it (app::prepare_design_in's rule).
  app::PreparedDesign prepared = app::prepare_design_in(settings, folder);
  return run_prepared(prepared, threads, progress);
}

py::object resume_design(const std::string& folder, unsigned threads, const py::object& progress) {
  // A finished design gives its result, as `design --resume` and run-design do.
  app::PreparedDesign prepared = app::prepare_resume(folder, true);
  return run_prepared(prepared, threads, progress);
}

py::object read_design(const std::string& folder) { return to_python(app::design_folder_document(folder)); }

}  // namespace

void bind_designs(py::module_& m) {
  m.def("design", &design, py::arg("mission"), py::arg("budget"), py::arg("architectures"), py::arg("flavours"),
        py::arg("seed"), py::arg("folder"), py::arg("threads") = 0, py::arg("progress") = py::none(),
        py::arg("pseudo_reality") = "", py::arg("pseudo_reality_samples") = "", py::arg("method") = "automode",
        "A design in-process, as `swarmdesign design` runs it; the final report document.");
  m.def("design_methods", [] { return to_python(app::design_methods_document()); },
        "The design methods, one dict each (name, title, summary, has_design_space).");
  m.def("resume_design", &resume_design, py::arg("folder"), py::arg("threads") = 0, py::arg("progress") = py::none(),
        "Continues the design kept in a folder (as `design --resume DIR`); the final report document.");
  m.def("read_design", &read_design, py::arg("folder"), "A design folder's progress, race log and convergence.");
  m.def("parse_budget", &app::parse_budget, py::arg("text"), "A design budget, read as the CLI reads --budget.");
  m.def("parse_seed", &app::parse_seed, py::arg("text"), "A seed, read as the CLI reads --seed.");
  m.def("parse_seed_range", &app::parse_seed_range, py::arg("text"), "Seeds \"S\" or \"A-B\", read as the CLI reads --seeds.");
  m.def("random_seed", &app::random_seed, "A fresh seed in 1..2^31-1, as a design without --seed gets.");
}

}  // namespace sd::python
