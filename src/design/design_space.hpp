#pragma once
// Which design space a user asked for: the architecture flags (--fsm, --bt) and the flavour
// flags (--chocolate ...) of the design commands (cli/design_flags.cpp), resolved against what
// the module catalogue has today. Flags name what may be used; none given means everything
// that exists.
#include <string>
#include <vector>

#include "design/fsm_space.hpp"
#include "design/parameter_space.hpp"
#include "modules/catalogue.hpp"

namespace sd::design {

struct DesignSpaceRequest {
  bool fsm = false, bt = false;    // architecture flags as given
  std::vector<Flavour> flavours;   // flavour flags as given (empty: all)
};

/// The space a design explores, named as the designs table stores it.
struct DesignSpaceChoice {
  std::vector<std::string> architectures;  // "fsm", "bt", or both (then the architecture is tuned)
  std::vector<Flavour> flavours;           // those that have modules
  std::vector<std::string> notes;          // what was asked for but left out, for the user

  std::string architectures_text() const;  // "fsm"
  std::string flavours_text() const;       // "chocolate,maple"
};

/// Throws std::invalid_argument with a message for the user: a chosen flavour without modules
/// ("no Arlequin modules are available yet").
DesignSpaceChoice resolve_design_space(const DesignSpaceRequest& request);

/// The parameter space of a resolved choice.
ParameterSpace build_design_space(const DesignSpaceChoice& choice);

/// Reads back what architectures_text()/flavours_text() wrote (a stored design).
DesignSpaceRequest request_from_text(const std::string& architectures, const std::string& flavours);
/// The same from lists of names ("fsm", "bt"; "chocolate", ...); std::invalid_argument naming
/// an unknown one.
DesignSpaceRequest request_from_names(const std::vector<std::string>& architectures,
                                      const std::vector<std::string>& flavours);

/// The items of a comma-separated list, empty ones left out ("fsm,bt" -> {"fsm", "bt"}).
std::vector<std::string> split_list(const std::string& text);

}  // namespace sd::design
