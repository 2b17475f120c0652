#pragma once
// The design space of a request, written as the files with which the real irace 3.5 drives
// SwarmDesign's evaluator (design/irace_export.hpp), after the same checks a native design
// makes (mission, flavours, irace's minimum budget).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "design/design_space.hpp"

namespace sd::app {

struct IraceExportRequest {
  std::string mission;
  design::DesignSpaceRequest space;
  long long budget = 5000;
  std::uint64_t seed = 0;  // 0: irace picks
  int iterations = 0;      // 0: irace's default
  std::filesystem::path out;
  std::string executable;  // the swarmdesign that target-runner calls
};

/// The notes of the resolved space (what was asked for but left out).
std::vector<std::string> export_irace(const IraceExportRequest& request);

}  // namespace sd::app
