#include "app/protocol_requests.hpp"

#include "app/errors.hpp"

namespace sd::app {

experiments::Protocol requested_protocol(const ProtocolRequest& r, const FileScope& scope) {
  const int given = (r.builtin.empty() ? 0 : 1) + (r.file.empty() ? 0 : 1) + (r.text.empty() ? 0 : 1);
  if (given > 1) throw InvalidRequest("name a built-in experiment or give a protocol (--file, text), not both");
  if (given == 0)
    throw InvalidRequest("name an experiment (validation, combination, architecture) or give a protocol (--file PROTOCOL)");
  if (r.builtin.empty() && r.evostick)
    throw InvalidRequest("--evostick adds a condition to a built-in experiment; write it in the protocol");
  try {
    experiments::Protocol protocol;
    if (!r.builtin.empty()) protocol = experiments::builtin_protocol(r.builtin, r.evostick);
    else if (!r.text.empty()) protocol = experiments::parse_protocol_text(r.text, "protocol");
    else if (scope.is_local()) protocol = experiments::read_protocol_file(r.file);  // its own refusals, as ever
    else protocol = experiments::parse_protocol_text(scope.read(r.file, "protocol file"), r.file);
    return experiments::with_overrides(std::move(protocol), r.overrides);
  } catch (const experiments::ProtocolError& e) {
    throw InvalidRequest(e.what());
  }
}

PlannedExperiment plan_requested_experiment(const ProtocolRequest& request, const FileScope& scope) {
  const experiments::Protocol protocol = requested_protocol(request, scope);
  for (const auto& m : protocol.missions) load_requested_mission(m.mission, scope);
  return plan_experiment(protocol, scope);
}

}  // namespace sd::app
