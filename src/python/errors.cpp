// The engine's errors as Python exceptions, with the CLI's words (what `swarmdesign` prints
// after "swarmdesign: error: ", newlines joined into one line):
//   SwarmDesignError                          anything the engine refuses or fails at
//     InvalidRequestError (also ValueError)   a malformed request (the CLI's exit status 2)
//       MissionError                          a mission that cannot be loaded as asked
//       ConfigError                           a malformed configuration string
//       ExportError                           control software a code base cannot read
//     NotFoundError (also LookupError), ConflictError, AccessDeniedError, DesignFolderError
//       QuotaExceededError (a ConflictError)   past the account's quota; .quota: "disk" or "runs"
#include <pybind11/pybind11.h>

#include <algorithm>
#include <exception>
#include <new>
#include <string>

#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "control/config_string.hpp"
#include "core/bounded_file.hpp"
#include "experiments/protocol.hpp"
#include "export/legacy_string.hpp"
#include "missions/mission.hpp"
#include "python/bindings.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

struct Classes {
  PyObject* base = nullptr;
  PyObject* invalid = nullptr;
  PyObject* mission = nullptr;
  PyObject* config = nullptr;
  PyObject* export_refused = nullptr;
  PyObject* not_found = nullptr;
  PyObject* conflict = nullptr;
  PyObject* quota = nullptr;
  PyObject* access_denied = nullptr;
  PyObject* design_folder = nullptr;
};

Classes& classes() {
  static Classes c;  // the module holds a reference to each class for the process's life
  return c;
}

PyObject* make_class(py::module_& module, const char* name, const char* doc, py::tuple bases) {
  const std::string qualified = std::string("swarmdesign.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  module.add_object(name, py::handle(type));  // steals nothing: add_object increments
  return type;
}

void set_error(PyObject* type, const char* what) {
  std::string line = what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  PyErr_SetString(type, line.c_str());
}

/// The exception with its `quota` attribute set, as the page's answer has its "quota" field.
void set_quota_error(PyObject* type, const app::QuotaExceeded& e) {
  py::object error = py::reinterpret_borrow<py::object>(type)(std::string(e.what()));
  error.attr("quota") = e.quota;
  PyErr_SetObject(type, error.ptr());
}

}  // namespace

void bind_errors(py::module_& module) {
  Classes& c = classes();
  const py::handle exception(PyExc_Exception), value_error(PyExc_ValueError), lookup_error(PyExc_LookupError);
  c.base = make_class(module, "SwarmDesignError", "Anything SwarmDesign refuses or fails at (the CLI's exit status 1 or 2).",
                      py::make_tuple(exception));
  const py::handle base(c.base);
  c.invalid = make_class(module, "InvalidRequestError",
                         "A malformed request: a value out of its domain, an unknown name (the CLI's exit status 2).",
                         py::make_tuple(base, value_error));
  const py::handle invalid(c.invalid);
  c.mission = make_class(module, "MissionError", "A mission that cannot be loaded: unknown name, malformed or unreadable file.",
                         py::make_tuple(invalid));
  c.config = make_class(module, "ConfigError", "A malformed configuration string; the message names the token at fault.",
                        py::make_tuple(invalid));
  c.export_refused = make_class(module, "ExportError", "Control software that the asked ARGoS code base cannot read.",
                                py::make_tuple(invalid));
  c.not_found = make_class(module, "NotFoundError", "No such thing (project, design, experiment, file).",
                           py::make_tuple(base, lookup_error));
  c.conflict = make_class(module, "ConflictError", "The name is taken, or the thing is busy.", py::make_tuple(base));
  c.quota = make_class(module, "QuotaExceededError",
                       "Work or a file past the account's quota; its `quota` attribute says which: 'disk' or 'runs'.",
                       py::make_tuple(py::handle(c.conflict)));
  c.access_denied = make_class(module, "AccessDeniedError", "Not signed in, or a wrong password.", py::make_tuple(base));
  c.design_folder = make_class(module, "DesignFolderError",
                               "A design folder that cannot be used as asked (not a design, damaged, finished, ...).",
                               py::make_tuple(base));

  // pybind11's translator is a plain function pointer taking the exception_ptr by value.
  py::register_exception_translator([](std::exception_ptr error) {  // NOLINT(performance-unnecessary-value-param)
    if (!error) return;
    const Classes& k = classes();
    try {
      std::rethrow_exception(error);
    } catch (const py::error_already_set&) {
      throw;
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const MissionLoadError& e) {
      set_error(k.mission, e.what());
    } catch (const MissionError& e) {
      set_error(k.mission, e.what());
    } catch (const ConfigError& e) {
      set_error(k.config, e.what());
    } catch (const argos::ExportRefused& e) {
      set_error(k.export_refused, e.what());
    } catch (const app::NotFound& e) {
      set_error(k.not_found, e.what());
    } catch (const app::QuotaExceeded& e) {
      set_quota_error(k.quota, e);
    } catch (const app::Conflict& e) {
      set_error(k.conflict, e.what());
    } catch (const app::AccessDenied& e) {
      set_error(k.access_denied, e.what());
    } catch (const app::DesignFolderError& e) {
      set_error(k.design_folder, e.what());
    } catch (const std::exception& e) {
      const app::ErrorKind kind = app::classify(e);
      set_error(kind == app::ErrorKind::InvalidRequest || dynamic_cast<const FileReadError*>(&e) ? k.invalid : k.base, e.what());
    }
  });
}

}  // namespace sd::python
