// Missions (the catalogue, a name, a file, a JSON text) and control software (a configuration
// string of any flavour, read by the CLI's one parser) as Python objects.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <string>

#include "app/control_software_document.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/pseudo_realities.hpp"
#include "app/user_files.hpp"
#include "control/config_string.hpp"
#include "control/describe.hpp"
#include "export/legacy_string.hpp"
#include "missions/catalogue.hpp"
#include "missions/svg.hpp"
#include "python/bindings.hpp"
#include "python/json_objects.hpp"
#include "python/software_svg.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

/// A name or file as `--mission` takes it; a refusal in the CLI's words as MissionError.
std::shared_ptr<Mission> load(const std::string& name_or_path) {
  try {
    return std::make_shared<Mission>(app::load_requested_mission(name_or_path));
  } catch (const app::InvalidRequest& e) {
    throw MissionLoadError(e.what());
  }
}

ParseOptions parse_options(const std::string& legacy_flavour) {
  const auto flavour = flavour_from_name(legacy_flavour);
  if (!flavour) throw app::InvalidRequest("--legacy-flavour: unknown flavour '" + legacy_flavour + "'");
  ParseOptions options;
  options.legacy_flavour = *flavour;
  return options;
}

std::string architecture_name(Architecture architecture) {
  switch (architecture) {
    case Architecture::Fsm: return "fsm";
    case Architecture::BehaviourTree: return "bt";
    case Architecture::NeuralNetwork: return "nn";
  }
  return "?";
}

}  // namespace

void bind_missions_and_software(py::module_& m) {
  m.def("missions", [] { return to_python(app::missions_document(list_missions())); },
        "The mission catalogue (built-in and $SWARMDESIGN_HOME/missions) as `swarmdesign missions --json` lists it.");
  m.def("module_catalogue", [] { return to_python(app::catalogue_document()); },
        "Every module of the five flavours with its id, name, flavour and parameter domains.");

  py::class_<Mission, std::shared_ptr<Mission>>(m, "Mission", "A mission: arena, swarm, start, duration and objective.")
      // Paths as str or os.PathLike (pathlib.Path), as evaluate, trace and design take them.
      .def_static("load", [](const std::filesystem::path& file) {
            // A path, always: "aac.json" or "missions/aac.json", never a catalogue name.
            const std::string path = file.string();
            return load(is_mission_file(path) ? path : "./" + path);
          }, py::arg("path"), "A mission file, checked as `--mission FILE` checks it (at most 1 MiB, a regular file).")
      .def_static("builtin", [](const std::string& name) {
            if (is_mission_file(name)) throw MissionLoadError("unknown mission '" + name + "' (see `swarmdesign missions`)");
            return load(name);
          }, py::arg("name"), "A mission of the catalogue by name (see swarmdesign.missions()).")
      .def_static("named", [](const std::filesystem::path& name_or_path) { return load(name_or_path.string()); },
                  py::arg("name_or_path"), "A catalogue name or a file, as `--mission` reads it.")
      .def_static("from_json", [](const std::string& text, const std::string& source) {
            return std::make_shared<Mission>(parse_mission(text, source));
          }, py::arg("text"), py::arg("source") = "<python>", "A mission from the text of a mission file.")
      .def("in_pseudo_reality", [](const Mission& mission, const std::filesystem::path& pseudo_reality, std::uint64_t sample) {
            return std::make_shared<Mission>(app::in_requested_sample(mission, pseudo_reality.string(), std::to_string(sample)));
          }, py::arg("pseudo_reality"), py::arg("sample"),
          "The mission in sample `sample` (1, 2, ...) of a pseudo-reality (a shipped name or a file), as "
          "`evaluate --pseudo-reality SPEC --sample K` runs it and assess numbers it.")
      .def("with_arlequin_modules", [](const Mission& mission, const std::string& set) {
            return std::make_shared<Mission>(app::with_requested_arlequin_modules(mission, set));
          }, py::arg("module_set"), "The mission run with another Arlequin module set (swarmdesign, demiurge or a folder).")
      .def_property_readonly("name", [](const Mission& x) { return x.name; })
      .def_property_readonly("title", [](const Mission& x) { return x.title; })
      .def_property_readonly("origin", [](const Mission& x) { return x.origin; })
      .def_property_readonly("description", [](const Mission& x) { return x.description; })
      .def_property_readonly("source", [](const Mission& x) { return x.source; })
      .def_property_readonly("robots", [](const Mission& x) { return x.robots; })
      .def_property_readonly("ticks", [](const Mission& x) { return x.ticks; })
      .def_property_readonly("duration_s", [](const Mission& x) { return x.duration_s; })
      .def_property_readonly("direction", [](const Mission& x) { return std::string(direction_name(x.objective.direction)); })
      .def_property_readonly("objective", [](const Mission& x) { return x.objective.type; })
      .def_property_readonly("digest", [](const Mission& x) { return x.digest; })
      .def_property_readonly("text", [](const Mission& x) { return x.document; }, "The mission file's text as read.")
      .def("document", [](const Mission& x) { return to_python(app::mission_document(x)); },
           "The mission as `swarmdesign mission show --json` prints it.")
      .def("svg", [](const Mission& x) { return mission_svg(x); }, "The arena drawn as SVG (as `mission show --svg`).")
      .def("__repr__", [](const Mission& x) { return "<swarmdesign.Mission " + x.name + " (" + x.source + ")>"; });

  py::class_<ControlSoftware, std::shared_ptr<ControlSoftware>>(
      m, "ControlSoftware", "Control software: a finite-state machine, a behaviour tree or an EvoStick network.")
      .def_static("parse", [](const std::string& text, const std::string& legacy_flavour) {
            return std::make_shared<ControlSoftware>(parse_control_software(text, parse_options(legacy_flavour)));
          }, py::arg("text"), py::arg("legacy_flavour") = "chocolate",
          "Reads a configuration string (--fsm-config, --bt-config, --nn-config) with two-digit ids, or a legacy\n"
          "one with one-digit ids of `legacy_flavour` (chocolate, tuttifrutti, maple, coconut, arlequin).\n"
          "ConfigError names the token at fault.")
      .def_property_readonly("architecture", [](const ControlSoftware& s) { return architecture_name(s.architecture); },
                             "'fsm', 'bt' or 'nn'.")
      .def("to_string", [](const ControlSoftware& s) { return to_config_string(s); },
           "The canonical configuration string (two-digit ids), as `show-config --canonical` prints it.")
      .def("__str__", [](const ControlSoftware& s) { return to_config_string(s); })
      .def("describe", [](const ControlSoftware& s) { return describe(s); }, "A readable listing, as `show-config` prints it.")
      .def("dot", [](const ControlSoftware& s) { return to_dot(s); }, "Graphviz DOT, as `show-config --dot` prints it.")
      .def("svg", [](const ControlSoftware& s) { return software_svg(s); }, "A drawing as a standalone SVG document.")
      .def("document", [](const ControlSoftware& s) { return to_python(app::software_document(s)); },
           "The editor's drawing model (states or nodes, modules and parameters) as a dict.")
      .def("to_legacy", [](const ControlSoftware& s, const std::optional<std::string>& flavour) {
            argos::ExportOptions options;
            if (flavour) options.flavour = argos::export_flavour(*flavour);
            const argos::LegacyString legacy = argos::to_legacy_string(s, options);
            return py::make_tuple(legacy.text, std::string(flavour_name(legacy.flavour)), legacy.reader);
          }, py::arg("flavour") = py::none(),
          "The string an ARGoS3-AutoMoDe code base reads (as `export --argos`): (text, flavour, reader).\n"
          "ExportError when that code base cannot read it.")
      .def("__eq__", [](const ControlSoftware& a, const py::object& b) -> py::object {
            if (!py::isinstance<ControlSoftware>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
            return py::bool_(a == b.cast<const ControlSoftware&>());
          })
      .def("__hash__", [](const ControlSoftware& s) { return py::hash(py::str(to_config_string(s))); })
      .def("__repr__", [](const ControlSoftware& s) { return "<swarmdesign.ControlSoftware " + to_config_string(s) + ">"; });
}

}  // namespace sd::python
