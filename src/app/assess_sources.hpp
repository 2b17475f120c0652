#pragma once
// Where the control software to assess comes from besides strings (app/assess_job): design
// folders, the active project's designs by id and its saved software; each labelled, a
// design's best or, with `elites`, every final elite.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/assess_job.hpp"
#include "app/home.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

struct AssessSources {
  std::vector<std::string> design_folders;
  std::vector<std::int64_t> project_designs;  // of the user's project, by number
  std::vector<std::string> saved;             // saved software of that project, by name
  bool elites = false;
};

/// Appends what `sources` names to `out`. Saved software and project designs are those of
/// `user`'s project (`project`, or the active one): the caller says who asks (the CLI's signed-in
/// user, a server's session), so any front end can use it; nullopt when only folders are named.
/// When `mission` is empty it becomes that project's mission (when the project is read) or else
/// the first design's. NotFound for a missing saved name, design or folder; InvalidRequest for a
/// design with no result yet, or project sources without a user.
void add_software_to_assess(Home& home, const std::optional<storage::User>& user, const std::optional<std::string>& project,
                            const AssessSources& sources, std::vector<SoftwareToAssess>& out, std::string& mission);

}  // namespace sd::app
