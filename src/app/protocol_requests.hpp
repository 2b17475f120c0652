#pragma once
// One request for an experiment's protocol, however a front end fills it (the CLI's name,
// --file and flags; the web's JSON body; Python's arguments): a built-in protocol by name, a
// protocol file, or a protocol's text, with the same overrides (missions, designs, seeds,
// budget scale, name, pseudo-reality). The one place that turns it into a plan.
#include <nlohmann/json_fwd.hpp>

#include <optional>
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

/// The request as a JSON object, the one shape the web's body and Python's keywords share:
/// {"protocol": built-in name | "file": path | "text": protocol JSON, "evostick", "missions": [..],
///  "designs", "assessment_seeds", "budget_scale", "seed", "name", "pseudo_reality",
///  "pseudo_reality_samples"}; absent or null fields keep the protocol's own. InvalidRequest
/// naming the field at fault.
ProtocolRequest protocol_request_from_json(const nlohmann::json& body);

/// The protocol asked for: exactly one of builtin, file and text; InvalidRequest naming what is
/// wrong (the protocol's own one-line errors included).
experiments::Protocol requested_protocol(const ProtocolRequest& request, const FileScope& scope = FileScope::local());

/// The protocol planned, every mission it names read under `scope` first (a server: the
/// user's own files only).
PlannedExperiment plan_requested_experiment(const ProtocolRequest& request, const FileScope& scope = FileScope::local());

/// A plan and, when asked for, how long it would take with `threads` (0: all cores), its speed
/// measured now: what `experiment --dry-run`, the page's Plan and Python's plan_experiment show.
struct EstimatedPlan {
  PlannedExperiment plan;
  std::optional<DurationEstimate> estimate;
};
EstimatedPlan plan_with_estimate(const ProtocolRequest& request, const FileScope& scope,
                                 std::optional<unsigned> estimate_threads);
/// Its document (`experiment --dry-run --json`): plan_document with the estimate when there is one.
nlohmann::json estimated_plan_document(const EstimatedPlan& planned);

}  // namespace sd::app
