#pragma once
// One request for an experiment's protocol, however a front end fills it (the CLI's name,
// --file and flags; the web's JSON body; Python's arguments): a built-in protocol by name, a
// protocol file, or a protocol's text, with the same overrides (missions, designs, seeds,
// budget scale, name, pseudo-reality). The one place that turns it into a plan.
#include <string>

#include "app/experiment_job.hpp"
#include "app/user_files.hpp"
#include "experiments/protocol.hpp"

namespace sd::app {

struct ProtocolRequest {
  std::string builtin;    // validation | combination | architecture
  std::string file;       // a protocol file (read under the scope)
  std::string text;       // a protocol's text
  bool evostick = false;  // a built-in protocol: add the EvoStick baseline as a further condition
  experiments::ProtocolOverrides overrides{};
};

/// The protocol asked for: exactly one of builtin, file and text; InvalidRequest naming what is
/// wrong (the protocol's own one-line errors included).
experiments::Protocol requested_protocol(const ProtocolRequest& request, const FileScope& scope = FileScope::local());

/// The protocol planned, every mission it names read under `scope` first (a server: the
/// user's own files only).
PlannedExperiment plan_requested_experiment(const ProtocolRequest& request, const FileScope& scope = FileScope::local());

}  // namespace sd::app
