#pragma once
// Where the control software to assess comes from besides strings (app/assess_job): design
// folders, the active project's designs by id and its saved software; each labelled, a
// design's best or, with `elites`, every final elite.
#include <cstdint>
#include <string>
#include <vector>

#include "app/assess_job.hpp"

namespace sd::app {

struct AssessSources {
  std::vector<std::string> design_folders;
  std::vector<std::int64_t> project_designs;  // of the signed-in user's active project
  std::vector<std::string> saved;             // saved software of that project, by name
  bool elites = false;
};

/// Appends what `sources` names to `out`. When `mission` is empty it becomes the active
/// project's mission (when the project is read) or else the first design's. NotFound for a
/// missing saved name, design or folder; InvalidRequest for a design with no result yet.
void add_software_to_assess(const AssessSources& sources, std::vector<SoftwareToAssess>& out, std::string& mission);

}  // namespace sd::app
