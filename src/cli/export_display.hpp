#pragma once
// The ARGoS3-AutoMoDe form of control software as a report line (status --argos,
// test-design --argos); export_commands.cpp has the export commands themselves.
#include <string>

#include "control/control_software.hpp"

namespace sd::cli {

/// "<indent><what> for ARGoS3-AutoMoDe (flavour, program):" (what may be empty), then the string
/// on the next line, indented two more; or why there is none.
void print_argos_line(const ControlSoftware& software, const std::string& indent, const std::string& what);

}  // namespace sd::cli
