#pragma once
// The flags shared by design, irace-export and run-design: architectures and flavours; and a
// robust design's pseudo-realities (design, run-design).
#include <string>

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

/// A robust design's flags (design, run-design): --pseudo-reality SPEC and its samples.
struct RobustDesignFlags {
  std::string pseudo_realities, samples;
  bool any() const { return !pseudo_realities.empty() || !samples.empty(); }
};

void add_robust_design_flags(CLI::App& command, RobustDesignFlags& flags);

}  // namespace sd::cli
