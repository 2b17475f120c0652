#include "modules/catalogue.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace sd {

namespace {

ParameterSpec integer(std::string token, double lo, double hi, std::string meaning) {
  return {std::move(token), ParameterType::Integer, lo, hi, {}, std::move(meaning)};
}
ParameterSpec real(std::string token, double lo, double hi, std::string meaning) {
  return {std::move(token), ParameterType::Real, lo, hi, {}, std::move(meaning)};
}

std::vector<ModuleSpec> build_behaviours() {
  std::vector<ModuleSpec> b;
  // Chocolate (RM1.2, ARGoS3-AutoMoDe master).
  b.push_back({10, ModuleKind::Behaviour, "Exploration", {integer("rwm", 1, 100, "random-walk turn length bound (steps)")}, kProximityInput});
  b.push_back({11, ModuleKind::Behaviour, "Stop", {}, 0});
  b.push_back({12, ModuleKind::Behaviour, "Phototaxis", {}, kLightInput | kProximityInput});
  b.push_back({13, ModuleKind::Behaviour, "Anti-phototaxis", {}, kLightInput | kProximityInput});
  b.push_back({14, ModuleKind::Behaviour, "Attraction", {real("att", 1, 5, "attraction to neighbours (truncated to an integer)")}, kRangeAndBearingInput | kProximityInput});
  b.push_back({15, ModuleKind::Behaviour, "Repulsion", {real("rep", 1, 5, "repulsion from neighbours (truncated to an integer)")}, kRangeAndBearingInput | kProximityInput});
  return b;
}

std::vector<ModuleSpec> build_conditions() {
  std::vector<ModuleSpec> c;
  const auto probability = [] { return real("p", 0, 1, "probability of firing"); };
  c.push_back({10, ModuleKind::Condition, "BlackFloor", {probability()}, kGroundInput});
  c.push_back({11, ModuleKind::Condition, "GrayFloor", {probability()}, kGroundInput});
  c.push_back({12, ModuleKind::Condition, "WhiteFloor", {probability()}, kGroundInput});
  c.push_back({13, ModuleKind::Condition, "NeighborsCount",
               {integer("p", 1, 10, "neighbour threshold xi"), real("w", 0, 20, "steepness eta")}, kRangeAndBearingInput});
  c.push_back({14, ModuleKind::Condition, "InvertedNeighborsCount",
               {integer("p", 1, 10, "neighbour threshold xi"), real("w", 0, 20, "steepness eta")}, kRangeAndBearingInput});
  c.push_back({15, ModuleKind::Condition, "FixedProbability", {probability()}, 0});
  return c;
}

const std::vector<ModuleSpec>& table(ModuleKind kind) {
  static const std::vector<ModuleSpec> behaviours = build_behaviours();
  static const std::vector<ModuleSpec> conditions = build_conditions();
  return kind == ModuleKind::Behaviour ? behaviours : conditions;
}

std::string number_text(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::string_view flavour_name(Flavour flavour) {
  switch (flavour) {
    case Flavour::Chocolate: return "chocolate";
    case Flavour::TuttiFrutti: return "tuttifrutti";
    case Flavour::Coconut: return "coconut";
    case Flavour::Maple: return "maple";
    case Flavour::Arlequin: return "arlequin";
  }
  return "unknown";
}

std::optional<Flavour> flavour_from_name(std::string_view name) {
  for (const Flavour f : {Flavour::Chocolate, Flavour::TuttiFrutti, Flavour::Coconut, Flavour::Maple, Flavour::Arlequin})
    if (flavour_name(f) == name) return f;
  return std::nullopt;
}

bool ParameterSpec::accepts(double value) const {
  if (!std::isfinite(value)) return false;
  switch (type) {
    case ParameterType::Integer:
      return value >= min && value <= max && value == std::floor(value);
    case ParameterType::Real:
      return value >= min && value <= max;
    case ParameterType::Categorical:
      return std::find(values.begin(), values.end(), value) != values.end();
  }
  return false;
}

std::string ParameterSpec::domain_text() const {
  if (type == ParameterType::Categorical) {
    std::string text = "one of {";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + number_text(values[i]);
    return text + "}";
  }
  return std::string(type == ParameterType::Integer ? "an integer" : "a number") + " in [" + number_text(min) + ", " +
         number_text(max) + "]";
}

int ModuleSpec::parameter_index(std::string_view token) const {
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].token == token) return static_cast<int>(i);
  return -1;
}

std::span<const ModuleSpec> modules(ModuleKind kind) { return table(kind); }

const ModuleSpec* find_module(ModuleKind kind, int id) {
  for (const ModuleSpec& m : table(kind))
    if (m.id == id) return &m;
  return nullptr;
}

}  // namespace sd
