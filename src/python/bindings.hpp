#pragma once
// The parts of the swarmdesign._core module, one file each: errors (the exception classes and
// the one translation of the engine's errors), missions and control software, evaluations and
// traces, designs and design folders, accounts and experiments, the reality gap (assess).
// module.cpp calls them in order.
#include <pybind11/pybind11.h>

namespace sd::python {

void bind_errors(pybind11::module_& module);
void bind_missions_and_software(pybind11::module_& module);
void bind_evaluation(pybind11::module_& module);
void bind_designs(pybind11::module_& module);
void bind_accounts(pybind11::module_& module);
void bind_reality(pybind11::module_& module);

/// A mission could not be loaded as asked (an unknown name, a malformed or unreadable file):
/// raised in Python as swarmdesign.MissionError with the CLI's words.
struct MissionLoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sd::python
