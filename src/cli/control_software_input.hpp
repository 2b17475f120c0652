#pragma once
// Reading the control software a command was given: the tail of the command line
// (--fsm-config ...) or --config-file FILE, in the legacy flavour the user names.
#include <string>

#include "cli/command_registry.hpp"
#include "control/config_string.hpp"

namespace sd::cli {

struct ControlSoftwareOptions {
  std::string config_file;
  std::string legacy_flavour = "chocolate";
};

void add_control_software_options(CLI::App& command, ControlSoftwareOptions& options);
ControlSoftware read_control_software(const Context& context, const ControlSoftwareOptions& options);

}  // namespace sd::cli
