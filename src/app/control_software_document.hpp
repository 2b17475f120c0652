#pragma once
// Control software and the module catalogue as JSON, for an editor that draws them: the
// catalogue comes from modules/catalogue (so the editor and the parser can never disagree),
// and a drawing comes back through the one parser (control/config_string), so whatever the
// editor sends is checked exactly as a configuration string typed on the command line.
#include <nlohmann/json.hpp>

#include "control/control_software.hpp"

namespace sd::app {

/// Every module of the five flavours with its id, name, flavour and parameter domains, the
/// behaviour-tree node types and the architectures' size limits.
nlohmann::json catalogue_document();

/// The drawing model: {"architecture": "fsm", "states": [...]}, {"architecture": "bt",
/// "nodes": [...]} or {"architecture": "nn"} (src/web/API.md gives the shape). Parameters
/// are keyed by their token stem; inactive ones are left out.
nlohmann::json software_document(const ControlSoftware& software);

/// The control software a drawing describes, checked by printing it and parsing it back;
/// InvalidRequest naming the field or token at fault.
ControlSoftware software_from_document(const nlohmann::json& model);

/// The token a parser message names ('--rwm0' in "... '--rwm0' ..."), or "" when none.
std::string token_named_in(const std::string& message);

}  // namespace sd::app
