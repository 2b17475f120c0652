#pragma once
// A design space as a front end asks for it: the architectures and flavours as text ("fsm,bt",
// "chocolate,maple"; empty: the defaults) or as lists of names, read as the CLI's flags, the
// web's form and Python read them, with one refusal (InvalidRequest) for a bad one.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "design/design_space.hpp"

namespace sd::app {

design::DesignSpaceRequest design_space_request(const std::string& architectures, const std::string& flavours);
/// The same from lists of names (Python's architectures=[...], flavours=[...]).
design::DesignSpaceRequest design_space_request(const std::vector<std::string>& architectures,
                                                const std::vector<std::string>& flavours);

/// What the space holds: {"architectures", "flavours", "notes", "method", "minimum_budget" (the
/// method's, over this space), "methods" (those that search a design space, one line each)} (the
/// web's design form shows it as the user chooses). An empty method: automode.
nlohmann::json design_space_document(const std::string& architectures, const std::string& flavours,
                                     const std::string& method = "");

}  // namespace sd::app
