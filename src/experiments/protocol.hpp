#pragma once
// An experiment's protocol as data: which missions, with which budget, under which conditions
// (a design space, or the EvoStick baseline), how many independent designs per condition and
// how many fresh seeds assess each final design. The thesis' three experiments are built in;
// a user writes their own as a JSON file of the same shape
// (`swarmdesign experiment --file F`, format in src/experiments/README.md).
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "design/methods.hpp"

namespace sd::experiments {

/// A malformed protocol, with the path of the field at fault ("missions[1].budget: ...").
struct ProtocolError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// One condition on one mission. Conditions of the same name on several missions are one
/// condition of the experiment (its box plots, heat maps and Friedman test group them).
struct Condition {
  std::string name;
  std::string method{design::kAutoMoDe.name};      // a name of design/methods.hpp
  std::vector<std::string> architectures;          // "fsm", "bt" (methods with a design space)
  std::vector<std::string> flavours;               // "chocolate", ... (methods with a design space)
};

struct MissionPlan {
  std::string mission;       // catalogue name or mission file
  long long budget = 0;      // simulation runs per design, before budget_scale
  std::vector<Condition> conditions;
};

/// Assessment in pseudo-realities (Ligot & Birattari 2020): every final design also runs, on
/// the same assessment seeds, in samples 1..samples of a pseudo-reality specification.
struct PseudoRealityPlan {
  std::string spec;             // a shipped specification's name or a specification file
  int samples = 20;             // samples 1, 2, ..., samples
  /// The specification itself, filled in when the experiment is planned (the app layer reads
  /// `spec`), so that the experiment resumes with the very robot models it started with; null
  /// until then. A protocol file may also write it inline. Held as its JSON text (compact).
  std::string definition;
};

struct Protocol {
  std::string name;
  int designs = 10;               // independent designs per mission and condition
  int assessment_seeds = 20;      // fresh seeds each final design is scored on
  double budget_scale = 1.0;      // every budget is multiplied by it
  std::uint64_t seed = 1;         // every design's seed derives from it
  std::vector<MissionPlan> missions;
  std::optional<PseudoRealityPlan> pseudo_reality;  // none: the design model only
};

/// The thesis' "validation", "combination", "architecture", optionally with EvoStick as a
/// further condition on every mission.
Protocol builtin_protocol(std::string_view name, bool with_evostick = false);
std::vector<std::string> builtin_protocol_names();

/// Reads a protocol document; ProtocolError naming the field (unknown fields are refused, so
/// a typo cannot silently change an experiment).
Protocol protocol_from_json(const nlohmann::json& document);
nlohmann::json to_json(const Protocol& protocol);
/// A protocol file (JSON, comments allowed); ProtocolError naming the file and the field.
Protocol read_protocol_file(const std::string& path);
/// The same for a protocol's text, its errors naming `path` (empty: a text of no file, as a page or
/// Python sends it).
Protocol parse_protocol_text(const std::string& text, const std::string& path);

/// What the command line may change of a protocol.
struct ProtocolOverrides {
  std::optional<std::vector<std::string>> missions;  // keep these missions, in this order
  std::optional<int> designs, assessment_seeds;
  std::optional<double> budget_scale;
  std::optional<std::uint64_t> seed;
  std::optional<std::string> name;
  std::optional<std::string> pseudo_reality;  // --pseudo-reality SPEC (its samples: 20 unless given)
  std::optional<int> pseudo_reality_samples;  // --pseudo-reality-samples N
};
/// ProtocolError for a mission the protocol does not have or a value out of its domain.
Protocol with_overrides(Protocol protocol, const ProtocolOverrides& overrides);

/// The budget a design of this mission gets: budget x budget_scale, rounded (the optimiser's
/// minimum is applied by the job, which knows the design space).
long long scaled_budget(const Protocol& protocol, const MissionPlan& mission);

/// The names of the conditions in first-appearance order.
std::vector<std::string> condition_names(const Protocol& protocol);

}  // namespace sd::experiments
