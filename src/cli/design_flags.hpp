#pragma once
// The flags shared by design, irace-export and run-design: architectures, flavours, seed.
#include <cstdint>
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

/// A seed the user typed (a non-negative integer); UsageError otherwise.
std::uint64_t parse_seed(const std::string& text);
/// A fresh seed in 1..2^31-1 (irace's range) for a design the user gave none.
std::uint64_t random_seed();

/// A budget the user typed, checked to be a positive integer; UsageError otherwise.
long long parse_budget(const std::string& text);

}  // namespace sd::cli
