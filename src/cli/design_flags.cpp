#include "cli/design_flags.hpp"

#include <CLI/CLI.hpp>

namespace sd::cli {

design::DesignSpaceRequest DesignSpaceFlags::request() const {
  design::DesignSpaceRequest r;
  r.fsm = fsm;
  r.bt = bt;
  if (chocolate) r.flavours.push_back(Flavour::Chocolate);
  if (tuttifrutti) r.flavours.push_back(Flavour::TuttiFrutti);
  if (coconut) r.flavours.push_back(Flavour::Coconut);
  if (maple) r.flavours.push_back(Flavour::Maple);
  if (arlequin) r.flavours.push_back(Flavour::Arlequin);
  return r;
}

bool DesignSpaceFlags::any() const { return fsm || bt || chocolate || tuttifrutti || coconut || maple || arlequin; }

void add_design_space_flags(CLI::App& command, DesignSpaceFlags& flags) {
  command.add_flag("--fsm", flags.fsm, "Design probabilistic finite-state machines");
  command.add_flag("--bt", flags.bt, "Design behaviour trees (Maple topology); with --fsm too, the optimiser picks");
  command.add_flag("--chocolate", flags.chocolate, "Use the Chocolate modules");
  command.add_flag("--tuttifrutti", flags.tuttifrutti, "Use the TuttiFrutti modules");
  command.add_flag("--coconut", flags.coconut, "Use the Coconut modules");
  command.add_flag("--maple", flags.maple, "Use the Maple modules");
  command.add_flag("--arlequin", flags.arlequin, "Use the Arlequin modules");
}

void add_robust_design_flags(CLI::App& command, RobustDesignFlags& flags) {
  // One name per idea: --pseudo-reality, as assess, experiment and export-argos spell it.
  // --pseudo-realities (the first spelling) stays an alias for one release.
  command.add_option("--pseudo-reality,--pseudo-realities", flags.pseudo_realities,
                     "Design robust control software: race every candidate in samples of this pseudo-reality specification "
                     "(a shipped name, see `swarmdesign pseudo-realities`, or a .json file) instead of the design model "
                     "(--pseudo-realities: the old spelling, kept for one release)");
  command.add_option("--pseudo-reality-samples", flags.samples,
                     "With --pseudo-reality: the samples the race's instances are, A-B (default 101-120, so that "
                     "assess's default samples 1-20 stay unseen)");
}

}  // namespace sd::cli
