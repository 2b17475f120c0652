// The reality gap from Python: app::assess (what `swarmdesign assess` runs) on a list of
// labelled control software, against a shipped or user pseudo-reality specification; the
// assessment document `assess --json` prints.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/assess_job.hpp"
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

py::object assess(const std::shared_ptr<Mission>& mission,
                  const std::vector<std::pair<std::string, std::shared_ptr<ControlSoftware>>>& software,
                  const std::string& pseudo_reality, const std::vector<std::uint64_t>& samples,
                  const std::vector<std::uint64_t>& seeds, int threads, const py::object& progress) {
  if (threads < 0 || threads > kMaxThreads) throw app::InvalidRequest("threads: expected 0 (all cores) to 1024");
  const app::NamedPseudoReality spec = app::load_requested_pseudo_reality(pseudo_reality);
  app::AssessRequest request;
  for (const auto& [label, s] : software) request.software.push_back({label, *s});
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
  run_interruptibly([&] { assessment = app::assess(*mission, request); }, [&] { token.cancel(); },
                    [&] {
                      const std::size_t now = done.load();
                      if (progress.is_none() || now == reported) return;
                      reported = now;
                      progress(now, all.load());
                    });
  return to_python(app::assessment_document(assessment));
}

}  // namespace

void bind_reality(py::module_& m) {
  m.def("assess", &assess, py::arg("mission"), py::arg("software"), py::arg("pseudo_reality"), py::arg("samples"),
        py::arg("seeds"), py::arg("threads") = 0, py::arg("progress") = py::none(),
        "The assessment document of `swarmdesign assess --json` (app::assess).");
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
