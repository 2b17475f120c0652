#pragma once
// The flags shared by design, irace-export and run-design: architectures and flavours.
#include "cli/command_registry.hpp"
#include "design/design_space.hpp"

namespace sd::cli {

struct DesignSpaceFlags {
  bool fsm = false, bt = false;
  bool chocolate = false, tuttifrutti = false, coconut = false, maple = false, arlequin = false;
  design::DesignSpaceRequest request() const;
  bool any() const;
};

void add_design_space_flags(CLI::App& command, DesignSpaceFlags& flags);

}  // namespace sd::cli
