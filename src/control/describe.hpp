#pragma once
// Human-readable views of control software: a text listing and Graphviz DOT.
#include <string>

#include "control/control_software.hpp"

namespace sd {

/// "Attraction(att=5)" and the like.
std::string describe_module(const ModuleInstance& module, ModuleKind kind);
std::string describe(const ControlSoftware& software);
std::string to_dot(const ControlSoftware& software);

}  // namespace sd
