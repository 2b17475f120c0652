// swarmdesign._core: SwarmDesign's engine in-process for Python (the package python/swarmdesign
// wraps it). Every job is the one the CLI runs (src/app), so scores, traces and designs are
// the CLI's to the bit.
#include <pybind11/pybind11.h>

#include "python/bindings.hpp"

PYBIND11_MODULE(_core, module) {
  module.doc() = "SwarmDesign's engine (the swarmdesign package wraps it; use that).";
  module.attr("__version__") = SWARMDESIGN_VERSION;
  sd::python::bind_errors(module);
  sd::python::bind_missions_and_software(module);
  sd::python::bind_evaluation(module);
  sd::python::bind_designs(module);
  sd::python::bind_accounts(module);
  sd::python::bind_reality(module);
}
