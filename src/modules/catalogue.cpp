#include "modules/catalogue.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace sd {

namespace {

ParameterSpec integer(std::string token, double lo, double hi, std::string meaning) {
  return {std::move(token), ParameterType::Integer, lo, hi, {}, std::move(meaning), {}, {}};
}
ParameterSpec real(std::string token, double lo, double hi, std::string meaning) {
  return {std::move(token), ParameterType::Real, lo, hi, {}, std::move(meaning), {}, {}};
}
ParameterSpec categorical(std::string token, std::vector<double> values, std::string meaning) {
  const double lo = values.front(), hi = values.back();
  return {std::move(token), ParameterType::Categorical, lo, hi, std::move(values), std::move(meaning), {}, {}};
}
ParameterSpec only_if(ParameterSpec spec, std::string token, std::vector<double> values) {
  spec.active_if = std::move(token);
  spec.active_values = std::move(values);
  return spec;
}

ParameterSpec rwm() { return integer("rwm", 1, 100, "random-walk turn length bound (steps)"); }
ParameterSpec att() { return real("att", 1, 5, "attraction to neighbours (truncated to an integer)"); }
ParameterSpec rep() { return real("rep", 1, 5, "repulsion from neighbours (truncated to an integer)"); }
ParameterSpec cle() { return categorical("cle", {0, 4, 5, 6}, "LED colour shown: 0 off, 4 yellow, 5 magenta, 6 cyan"); }
ParameterSpec clr() { return categorical("clr", {1, 2, 3, 4, 5, 6}, "colour followed: 1 green, 2 blue, 3 red, 4 yellow, 5 magenta, 6 cyan"); }
ParameterSpec vel() { return categorical("vel", {1}, "speed factor of colour following"); }
std::vector<ParameterSpec> exploration_scheme() {
  return {categorical("exp", {0, 1, 2}, "exploration: 0 ballistic/avoid, 1 ballistic/random turn, 2 random walk"),
          only_if(rwm(), "exp", {1}), only_if(real("mu", 1, 3, "random-walk step-length exponent"), "exp", {2}),
          only_if(real("rho", 0, 1, "random-walk turning concentration"), "exp", {2})};
}
std::vector<ParameterSpec> plus(std::vector<ParameterSpec> a, const std::vector<ParameterSpec>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

constexpr std::uint8_t kProx = kProximityInput, kLight = kLightInput, kRab = kRangeAndBearingInput, kCam = kCameraInput;

std::vector<ModuleSpec> build_behaviours() {
  std::vector<ModuleSpec> b;
  // Chocolate (RM1.2, ARGoS3-AutoMoDe master) and Maple (the same six, with the same
  // parameters and inputs, as behaviour-tree actions; their laws are the BT branch's:
  // maple_behaviours.hpp).
  for (const int base : {10, 40}) {
    b.push_back({base + 0, ModuleKind::Behaviour, "Exploration", {rwm()}, kProx});
    b.push_back({base + 1, ModuleKind::Behaviour, "Stop", {}, 0});
    b.push_back({base + 2, ModuleKind::Behaviour, "Phototaxis", {}, kLight | kProx});
    b.push_back({base + 3, ModuleKind::Behaviour, "Anti-phototaxis", {}, kLight | kProx});
    b.push_back({base + 4, ModuleKind::Behaviour, "Attraction", {att()}, kRab | kProx});
    b.push_back({base + 5, ModuleKind::Behaviour, "Repulsion", {rep()}, kRab | kProx});
  }
  // TuttiFrutti (RM3.0): every behaviour shows the LED colour cle.
  b.push_back({20, ModuleKind::Behaviour, "Exploration", {rwm(), cle()}, kProx});
  b.push_back({21, ModuleKind::Behaviour, "Stop", {cle()}, 0});
  b.push_back({24, ModuleKind::Behaviour, "Attraction", {att(), cle()}, kRab | kProx});
  b.push_back({25, ModuleKind::Behaviour, "Repulsion", {rep(), cle()}, kRab | kProx});
  b.push_back({28, ModuleKind::Behaviour, "GoToColor", {vel(), cle(), clr()}, kCam | kProx});
  b.push_back({29, ModuleKind::Behaviour, "GoAwayColor", {vel(), cle(), clr()}, kCam | kProx});
  // Coconut (DEMI): the exploration scheme is a parameter of every moving behaviour.
  b.push_back({30, ModuleKind::Behaviour, "Exploration", exploration_scheme(), kProx});
  b.push_back({31, ModuleKind::Behaviour, "Stop", {}, 0});
  b.push_back({32, ModuleKind::Behaviour, "Phototaxis", exploration_scheme(), kLight | kProx});
  b.push_back({33, ModuleKind::Behaviour, "Anti-phototaxis", exploration_scheme(), kLight | kProx});
  b.push_back({34, ModuleKind::Behaviour, "Attraction", plus({att()}, exploration_scheme()), kRab | kProx});
  b.push_back({35, ModuleKind::Behaviour, "Repulsion", plus({rep()}, exploration_scheme()), kRab | kProx});
  // Arlequin: neural networks without parameters; every one reads the 25 inputs of
  // modules/arlequin.hpp.
  constexpr std::uint8_t kNetwork = kProx | kLight | kGroundInput | kRab;
  const char* arlequin[] = {"Exploration", "Stop", "Phototaxis", "Anti-phototaxis", "Attraction", "Repulsion"};
  for (int d = 0; d < 6; ++d) b.push_back({50 + d, ModuleKind::Behaviour, arlequin[d], {}, kNetwork});
  std::sort(b.begin(), b.end(), [](const ModuleSpec& x, const ModuleSpec& y) { return x.id < y.id; });
  return b;
}

std::vector<ModuleSpec> build_conditions() {
  std::vector<ModuleSpec> c;
  const auto probability = [] { return real("p", 0, 1, "probability of firing"); };
  const auto xi = [] { return integer("p", 1, 10, "neighbour threshold xi (ARGoS3-AutoMoDe master encoding)"); };
  const auto eta = [] { return real("w", 0, 20, "steepness eta"); };
  // The six Chocolate conditions exist in every flavour that uses them.
  for (const int base : {10, 20, 30, 40, 50}) {
    c.push_back({base + 0, ModuleKind::Condition, "BlackFloor", {probability()}, kGroundInput});
    c.push_back({base + 1, ModuleKind::Condition, "GrayFloor", {probability()}, kGroundInput});
    c.push_back({base + 2, ModuleKind::Condition, "WhiteFloor", {probability()}, kGroundInput});
    c.push_back({base + 3, ModuleKind::Condition, "NeighborsCount", {xi(), eta()}, kRab});
    c.push_back({base + 4, ModuleKind::Condition, "InvertedNeighborsCount", {xi(), eta()}, kRab});
    c.push_back({base + 5, ModuleKind::Condition, "FixedProbability", {probability()}, 0});
  }
  c.push_back({27, ModuleKind::Condition, "ColorDetection",
               {probability(), categorical("l", {1, 2, 3, 4, 5, 6}, "colour detected: 1 green ... 6 cyan")}, kCam});
  std::sort(c.begin(), c.end(), [](const ModuleSpec& x, const ModuleSpec& y) { return x.id < y.id; });
  return c;
}

std::vector<ModuleSpec> checked(std::vector<ModuleSpec> table) {
  // ModuleInstance keeps parameters in a fixed array: no module may have more.
  for (const ModuleSpec& m : table)
    if (m.parameters.size() > static_cast<std::size_t>(kMaxModuleParameters)) std::abort();
  return table;
}

const std::vector<ModuleSpec>& table(ModuleKind kind) {
  static const std::vector<ModuleSpec> behaviours = checked(build_behaviours());
  static const std::vector<ModuleSpec> conditions = checked(build_conditions());
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

bool ModuleSpec::parameter_active(std::size_t p, const std::array<double, kMaxModuleParameters>& values) const {
  const ParameterSpec& spec = parameters[p];
  if (spec.active_if.empty()) return true;
  const int other = parameter_index(spec.active_if);
  if (other < 0) return false;
  const double v = values[static_cast<std::size_t>(other)];
  return std::find(spec.active_values.begin(), spec.active_values.end(), v) != spec.active_values.end();
}

std::uint32_t palette_color(int index) {
  static constexpr std::uint32_t kPalette[] = {0x000000, 0x00ff00, 0x0000ff, 0xff0000, 0xffff00, 0xff00ff, 0x00ffff};
  return index >= 0 && index <= 6 ? kPalette[index] : 0;
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
