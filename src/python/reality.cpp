// The reality gap from Python: app::assess (what `swarmdesign assess` runs) on a list of
// labelled control software, against a shipped or user pseudo-reality specification; the
// assessment document `assess --json` prints.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/accounts.hpp"
#include "app/assess_job.hpp"
#include "app/assess_sources.hpp"
#include "app/home.hpp"
#include "app/cancel_token.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/pseudo_realities.hpp"
#include "python/bindings.hpp"
#include "python/interruptible.hpp"
#include "python/json_objects.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

constexpr int kMaxThreads = 1024;

/// app::assess on `software` in `mission`, Ctrl-C cancelling it between batches.
py::object run_assessment(const Mission& mission, std::vector<app::SoftwareToAssess> software,
                          const std::string& pseudo_reality, const std::vector<std::uint64_t>& samples,
                          const std::vector<std::uint64_t>& seeds, int threads, const py::object& progress) {
  if (threads < 0 || threads > kMaxThreads) throw app::InvalidRequest("threads: expected 0 (all cores) to 1024");
  const app::NamedPseudoReality spec = app::load_requested_pseudo_reality(pseudo_reality);
  app::AssessRequest request;
  request.software = std::move(software);
  request.spec = spec.spec;
  request.spec_reference = spec.reference;
  request.samples = samples;
  request.seeds = seeds;
  request.threads = threads;
  app::assess_runs(request);  // the one limit, before any run
  app::CancelToken token;
  request.cancel = &token;
  std::atomic<std::size_t> done{0}, all{0};
  std::size_t reported = 0;
  request.progress = [&](std::size_t d, std::size_t a) {
    all.store(a);
    done.store(d);
  };
  app::Assessment assessment;
  run_interruptibly([&] { assessment = app::assess(mission, request); }, [&] { token.cancel(); },
                    [&] {
                      const std::size_t now = done.load();
                      if (progress.is_none() || now == reported) return;
                      reported = now;
                      progress(now, all.load());
                    });
  return to_python(app::assessment_document(assessment));
}

py::object assess(const std::shared_ptr<Mission>& mission,
                  const std::vector<std::pair<std::string, std::shared_ptr<ControlSoftware>>>& software,
                  const std::string& pseudo_reality, const std::vector<std::uint64_t>& samples,
                  const std::vector<std::uint64_t>& seeds, int threads, const py::object& progress) {
  std::vector<app::SoftwareToAssess> labelled;
  labelled.reserve(software.size());
  for (const auto& [label, s] : software) labelled.push_back({label, *s});
  return run_assessment(*mission, std::move(labelled), pseudo_reality, samples, seeds, threads, progress);
}

// A project's designs (their bests, or every final elite) and saved software, read as
// `assess --project-design/--saved` reads them (app::add_software_to_assess) for the
// signed-in user, in the project's mission unless one is named.
py::object account_assess(const std::optional<std::string>& home_folder, const std::optional<std::string>& project,
                          const std::vector<std::int64_t>& designs, const std::vector<std::string>& saved, bool elites,
                          const std::string& mission_name, const std::string& pseudo_reality,
                          const std::vector<std::uint64_t>& samples, const std::vector<std::uint64_t>& seeds, int threads,
                          const py::object& progress) {
  auto home = home_folder ? std::make_unique<app::Home>(*home_folder) : std::make_unique<app::Home>();
  const storage::User user = app::signed_in_user(*home);
  std::vector<app::SoftwareToAssess> software;
  std::string mission = mission_name;
  app::add_software_to_assess(*home, user, project, {{}, designs, saved, elites}, software, mission);
  if (software.empty()) throw app::InvalidRequest("nothing to assess: name designs or saved software of the project");
  return run_assessment(app::load_requested_mission(mission), std::move(software), pseudo_reality, samples, seeds, threads,
                        progress);
}

}  // namespace

void bind_reality(py::module_& m) {
  m.def("assess", &assess, py::arg("mission"), py::arg("software"), py::arg("pseudo_reality"), py::arg("samples"),
        py::arg("seeds"), py::arg("threads") = 0, py::arg("progress") = py::none(),
        "The assessment document of `swarmdesign assess --json` (app::assess).");
  m.def("account_assess", &account_assess, py::arg("home"), py::arg("project"), py::arg("designs"), py::arg("saved"),
        py::arg("elites"), py::arg("mission"), py::arg("pseudo_reality"), py::arg("samples"), py::arg("seeds"),
        py::arg("threads"), py::arg("progress"),
        "A project's designs and saved software across the reality gap (`assess --project-design/--saved --json`).");
  m.def("parse_sample_range", &app::parse_sample_range, py::arg("text"),
        "Pseudo-reality samples \"K\" or \"A-B\", read as `assess --samples` reads them.");
  m.def("pseudo_realities", [] { return to_python(app::pseudo_realities_document()); },
        "The shipped pseudo-realities (`pseudo-realities --json`).");
  m.def("pseudo_reality_samples", [](const std::string& name_or_path, const std::string& mission, const std::string& samples) {
          return to_python(app::pseudo_reality_samples_document(name_or_path, mission, samples));
        }, py::arg("name_or_path"), py::arg("mission"), py::arg("samples"),
        "A specification's samples beside the design model (`pseudo-realities NAME --json`).");
  m.def("pseudo_reality_document", [](const std::string& name_or_path) {
          const app::NamedPseudoReality spec = app::load_requested_pseudo_reality(name_or_path);
          py::dict out;
          out["reference"] = spec.reference;
          out["text"] = spec.document;
          return out;
        }, py::arg("name_or_path"), "A pseudo-reality specification (a shipped name or a file): its reference and text.");
}

}  // namespace sd::python
