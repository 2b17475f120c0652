#pragma once
// Pseudo-realities (Ligot & Birattari, "Simulation-only experiments to mimic the effects of
// the reality gap in the automatic design of robot swarms", Swarm Intelligence 14, 2020):
// robot models other than the one a design ran in (the *design model*), to see how much of
// a design's performance survives a change of model, and whether design methods keep their
// ranks. A specification says, per knob of the robot model, a fixed value or a range; sample
// k (k = 1, 2, ...) is one robot model drawn from it, a pure function of (specification, k,
// design model): the same on every machine and at every thread count.
//
// File format (pseudo-realities/*.json; a knob not named keeps its design value):
//   {"name": "...", "description": "...", "source": "...",
//    "knobs": {"wheel_noise": 0.15,                      fixed
//              "rab_loss": {"uniform": [0.8, 0.95]},     uniform in an interval
//              "light_noise": {"around": 0.5}}}          uniform in [v (1 - r), v (1 + r)] around
//                                                        the design value v, within the domain
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "simulator/robot_model.hpp"

namespace sd {

/// A malformed specification; the message names the field ("knobs.rab_loss: must be in [0, 1]").
struct PseudoRealityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct KnobLaw {
  enum class Kind { Fixed, Uniform, Around } kind = Kind::Fixed;
  double a = 0.0, b = 0.0;  // Fixed: a; Uniform: [a, b]; Around: relative half-width a
};

struct PseudoRealitySpec {
  std::string name, description, source;
  /// Per entry of kRobotKnobs: how the knob is drawn; empty: its design value.
  std::vector<std::optional<KnobLaw>> laws;
  std::string digest;  // 16 hex digits over the canonical document: samples are drawn from it

  /// Sample k >= 1: the design model with every named knob drawn. Knobs are drawn in
  /// kRobotKnobs' order, each with one draw whatever its law, so sample k of a knob does not
  /// depend on the other knobs' laws.
  RobotModel sample(const RobotModel& design, std::uint64_t k) const;
  /// Whether a knob with a range is named (samples differ from one another).
  bool varies() const;
};

/// Parses a specification document; `what` names it in errors ("pseudo-reality file x.json").
PseudoRealitySpec parse_pseudo_reality(const std::string& text, const std::string& what);

/// The specifications shipped in pseudo-realities/ (compiled in), by name.
struct BuiltinPseudoReality {
  std::string_view name;
  std::string_view json;
};
std::span<const BuiltinPseudoReality> builtin_pseudo_realities();
/// A shipped specification by name, or nullopt.
std::optional<PseudoRealitySpec> builtin_pseudo_reality(const std::string& name);

}  // namespace sd
