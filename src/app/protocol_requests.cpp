#include "app/protocol_requests.hpp"

#include <nlohmann/json.hpp>

#include <optional>

#include "app/documents/experiments.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"

namespace sd::app {

namespace {

using nlohmann::json;

bool given(const json& body, const char* key) { return body.contains(key) && !body.at(key).is_null(); }

std::string text(const json& body, const char* key) {
  const json& value = body.at(key);
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return value.dump();
  throw InvalidRequest(std::string(key) + " must be text or a whole number");
}

std::optional<int> whole_number(const json& body, const char* key) {
  if (!given(body, key)) return std::nullopt;
  if (!body.at(key).is_number_integer()) throw InvalidRequest(std::string(key) + " must be a whole number");
  return body.at(key).get<int>();
}

}  // namespace

ProtocolRequest protocol_request_from_json(const json& body) {
  if (!body.is_object()) throw InvalidRequest("the experiment request must be a JSON object");
  ProtocolRequest r;
  if (given(body, "text")) r.text = text(body, "text");
  if (given(body, "file")) r.file = text(body, "file");
  if (given(body, "protocol")) r.builtin = text(body, "protocol");
  if (given(body, "evostick")) {
    if (!body.at("evostick").is_boolean()) throw InvalidRequest("evostick must be true or false");
    r.evostick = body.at("evostick").get<bool>();
  }
  experiments::ProtocolOverrides& o = r.overrides;
  if (given(body, "missions")) {
    if (!body.at("missions").is_array()) throw InvalidRequest("missions must be a list of mission names");
    o.missions.emplace();
    for (const json& m : body.at("missions")) {
      if (!m.is_string()) throw InvalidRequest("missions must be a list of mission names");
      o.missions->push_back(m.get<std::string>());
    }
  }
  o.designs = whole_number(body, "designs");
  o.assessment_seeds = whole_number(body, "assessment_seeds");
  if (given(body, "budget_scale")) {
    if (!body.at("budget_scale").is_number()) throw InvalidRequest("budget_scale must be a number");
    o.budget_scale = body.at("budget_scale").get<double>();
  }
  if (given(body, "seed")) o.seed = parse_seed(text(body, "seed"));
  if (given(body, "name") && !text(body, "name").empty()) o.name = text(body, "name");
  // Every final design also assessed in a pseudo-reality (experiment --pseudo-reality).
  if (given(body, "pseudo_reality") && !text(body, "pseudo_reality").empty()) o.pseudo_reality = text(body, "pseudo_reality");
  o.pseudo_reality_samples = whole_number(body, "pseudo_reality_samples");
  return r;
}

experiments::Protocol requested_protocol(const ProtocolRequest& r, const FileScope& scope) {
  const int given = (r.builtin.empty() ? 0 : 1) + (r.file.empty() ? 0 : 1) + (r.text.empty() ? 0 : 1);
  if (given > 1) throw InvalidRequest("name a built-in experiment or give a protocol (--file, text), not both");
  if (given == 0)
    throw InvalidRequest("name an experiment (validation, combination, architecture, methods) or give a protocol (--file PROTOCOL)");
  if (r.builtin.empty() && r.evostick)
    throw InvalidRequest("--evostick adds a condition to a built-in experiment; write it in the protocol");
  try {
    experiments::Protocol protocol;
    if (!r.builtin.empty()) protocol = experiments::builtin_protocol(r.builtin, r.evostick);
    else if (!r.text.empty()) protocol = experiments::parse_protocol_text(r.text, "");  // a text: no file to name
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

EstimatedPlan plan_with_estimate(const ProtocolRequest& request, const FileScope& scope,
                                 std::optional<unsigned> estimate_threads) {
  EstimatedPlan out{plan_requested_experiment(request, scope), std::nullopt};
  if (estimate_threads) out.estimate = estimate_duration(out.plan, *estimate_threads);
  return out;
}

nlohmann::json estimated_plan_document(const EstimatedPlan& planned) {
  return plan_document(planned.plan, planned.estimate ? &*planned.estimate : nullptr);
}

}  // namespace sd::app
