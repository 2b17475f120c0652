#include "modules/catalogue.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "modules/laws.hpp"

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

ModuleSpec spec(int id, ModuleKind kind, std::string name, std::vector<ParameterSpec> parameters, std::uint8_t inputs) {
  ModuleSpec m{};
  m.id = id;
  m.kind = kind;
  m.name = std::move(name);
  m.parameters = std::move(parameters);
  m.inputs = inputs;
  return m;
}
ModuleSpec behaviour(int id, std::string name, std::vector<ParameterSpec> parameters, std::uint8_t inputs, const BehaviourLaw& law) {
  ModuleSpec m = spec(id, ModuleKind::Behaviour, std::move(name), std::move(parameters), inputs);
  m.behaviour = law;
  return m;
}
ModuleSpec condition(int id, std::string name, std::vector<ParameterSpec> parameters, std::uint8_t inputs, const ConditionLaw& law) {
  ModuleSpec m = spec(id, ModuleKind::Condition, std::move(name), std::move(parameters), inputs);
  m.condition = law;
  return m;
}

std::vector<ModuleSpec> build_behaviours() {
  std::vector<ModuleSpec> b;
  // Chocolate (RM1.2, ARGoS3-AutoMoDe master).
  b.push_back(behaviour(10, "Exploration", {rwm()}, kProx, laws::chocolate::exploration));
  b.push_back(behaviour(11, "Stop", {}, 0, laws::stop));
  b.push_back(behaviour(12, "Phototaxis", {}, kLight | kProx, laws::chocolate::phototaxis));
  b.push_back(behaviour(13, "Anti-phototaxis", {}, kLight | kProx, laws::chocolate::anti_phototaxis));
  b.push_back(behaviour(14, "Attraction", {att()}, kRab | kProx, laws::chocolate::attraction));
  b.push_back(behaviour(15, "Repulsion", {rep()}, kRab | kProx, laws::chocolate::repulsion));
  // TuttiFrutti (RM3.0): every behaviour shows the LED colour cle.
  b.push_back(behaviour(20, "Exploration", {rwm(), cle()}, kProx, laws::tuttifrutti::exploration));
  b.push_back(behaviour(21, "Stop", {cle()}, 0, laws::tuttifrutti::stop));
  b.push_back(behaviour(24, "Attraction", {att(), cle()}, kRab | kProx, laws::tuttifrutti::attraction));
  b.push_back(behaviour(25, "Repulsion", {rep(), cle()}, kRab | kProx, laws::tuttifrutti::repulsion));
  b.push_back(behaviour(28, "GoToColor", {vel(), cle(), clr()}, kCam | kProx, laws::tuttifrutti::go_to_color));
  b.push_back(behaviour(29, "GoAwayColor", {vel(), cle(), clr()}, kCam | kProx, laws::tuttifrutti::go_away_color));
  // Coconut (DEMI): the exploration scheme is a parameter of every moving behaviour.
  b.push_back(behaviour(30, "Exploration", exploration_scheme(), kProx, laws::coconut::exploration));
  b.push_back(behaviour(31, "Stop", {}, 0, laws::stop));
  b.push_back(behaviour(32, "Phototaxis", exploration_scheme(), kLight | kProx, laws::coconut::phototaxis));
  b.push_back(behaviour(33, "Anti-phototaxis", exploration_scheme(), kLight | kProx, laws::coconut::anti_phototaxis));
  b.push_back(behaviour(34, "Attraction", plus({att()}, exploration_scheme()), kRab | kProx, laws::coconut::attraction));
  b.push_back(behaviour(35, "Repulsion", plus({rep()}, exploration_scheme()), kRab | kProx, laws::coconut::repulsion));
  // Maple: Chocolate's six, with the same parameters and inputs, as behaviour-tree actions;
  // their laws are the BT branch's (maple_behaviours.hpp).
  b.push_back(behaviour(40, "Exploration", {rwm()}, kProx, laws::maple::exploration));
  b.push_back(behaviour(41, "Stop", {}, 0, laws::stop));
  b.push_back(behaviour(42, "Phototaxis", {}, kLight | kProx, laws::maple::phototaxis));
  b.push_back(behaviour(43, "Anti-phototaxis", {}, kLight | kProx, laws::maple::anti_phototaxis));
  b.push_back(behaviour(44, "Attraction", {att()}, kRab | kProx, laws::maple::attraction));
  b.push_back(behaviour(45, "Repulsion", {rep()}, kRab | kProx, laws::maple::repulsion));
  // Arlequin: neural networks without parameters; every one reads the 25 inputs of
  // modules/arlequin.hpp.
  constexpr std::uint8_t kNetwork = kProx | kLight | kGroundInput | kRab;
  const char* arlequin[] = {"Exploration", "Stop", "Phototaxis", "Anti-phototaxis", "Attraction", "Repulsion"};
  for (int d = 0; d < 6; ++d) b.push_back(behaviour(50 + d, arlequin[d], {}, kNetwork, laws::arlequin::network[d]));
  return b;
}

std::vector<ModuleSpec> build_conditions() {
  std::vector<ModuleSpec> c;
  const auto probability = [] { return real("p", 0, 1, "probability of firing"); };
  const auto xi = [] { return integer("p", 1, 10, "neighbour threshold xi (ARGoS3-AutoMoDe master encoding)"); };
  const auto eta = [] { return real("w", 0, 20, "steepness eta"); };
  // The six Chocolate conditions exist in every flavour that uses them; the floor ones read
  // the floor filter of the flavour's reference model (TuttiFrutti's RM3.0, branch tuttifrutti of
  // demiurge-epuck-dao, filters the floor as RM1.2).
  for (const int base : {10, 20, 30, 40, 50}) {
    const laws::FloorLaws& floors = base == 30 || base == 50 ? laws::demiurge_floor : laws::rm1_floor;
    c.push_back(condition(base + 0, "BlackFloor", {probability()}, kGroundInput, floors.black));
    c.push_back(condition(base + 1, "GrayFloor", {probability()}, kGroundInput, floors.gray));
    c.push_back(condition(base + 2, "WhiteFloor", {probability()}, kGroundInput, floors.white));
    c.push_back(condition(base + 3, "NeighborsCount", {xi(), eta()}, kRab, laws::neighbours_count));
    c.push_back(condition(base + 4, "InvertedNeighborsCount", {xi(), eta()}, kRab, laws::inverted_neighbours_count));
    c.push_back(condition(base + 5, "FixedProbability", {probability()}, 0, laws::fixed_probability));
  }
  c.push_back(condition(27, "ColorDetection",
                        {probability(), categorical("l", {1, 2, 3, 4, 5, 6}, "colour detected: 1 green ... 6 cyan")}, kCam,
                        laws::color_detection));
  return c;
}

std::string module_text(const ModuleSpec& m) {
  std::string text = "module ";
  text += std::to_string(m.id);
  text += " (";
  text += m.name;
  text += ")";
  return text;
}

[[noreturn]] void refuse(const ModuleSpec& m, std::string_view why, std::string_view name = {}) {
  std::string text = module_text(m);
  text += ' ';
  text += why;
  text += name;
  throw std::logic_error(text);
}

/// The spec of an id the catalogue lacks: its law throws, so a bad id never stops a robot
/// silently.
const ModuleSpec& unknown_module(ModuleKind kind) {
  static const ModuleSpec behaviour = [] {
    ModuleSpec m = spec(-1, ModuleKind::Behaviour, "unknown", {}, 0);
    m.behaviour = laws::unknown_behaviour;
    return m;
  }();
  static const ModuleSpec condition = [] {
    ModuleSpec m = spec(-1, ModuleKind::Condition, "unknown", {}, 0);
    m.condition = laws::unknown_condition;
    return m;
  }();
  return kind == ModuleKind::Behaviour ? behaviour : condition;
}

struct Catalogue {
  std::vector<ModuleSpec> behaviours, conditions;
  std::array<const ModuleSpec*, 100> behaviour_by_id{}, condition_by_id{};  // two-digit ids
};

const Catalogue& catalogue() {
  static const Catalogue c = [] {
    Catalogue built{with_resolved_laws(build_behaviours()), with_resolved_laws(build_conditions()), {}, {}};
    built.behaviour_by_id.fill(&unknown_module(ModuleKind::Behaviour));
    built.condition_by_id.fill(&unknown_module(ModuleKind::Condition));
    for (const ModuleSpec& m : built.behaviours) built.behaviour_by_id.at(static_cast<std::size_t>(m.id)) = &m;
    for (const ModuleSpec& m : built.conditions) built.condition_by_id.at(static_cast<std::size_t>(m.id)) = &m;
    return built;
  }();
  return c;
}

const std::vector<ModuleSpec>& table(ModuleKind kind) {
  return kind == ModuleKind::Behaviour ? catalogue().behaviours : catalogue().conditions;
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

const ModuleSpec& module_to_run(ModuleKind kind, int id) {
  const Catalogue& c = catalogue();
  const auto& by_id = kind == ModuleKind::Behaviour ? c.behaviour_by_id : c.condition_by_id;
  return static_cast<unsigned>(id) < by_id.size() ? *by_id[static_cast<std::size_t>(id)] : unknown_module(kind);
}

std::vector<ModuleSpec> with_resolved_laws(std::vector<ModuleSpec> table) {
  std::sort(table.begin(), table.end(), [](const ModuleSpec& x, const ModuleSpec& y) { return x.id < y.id; });
  for (std::size_t k = 0; k < table.size(); ++k) {
    ModuleSpec& m = table[k];
    if (m.id < 0 || m.id > 99) refuse(m, "has no two-digit id");
    if (k > 0 && table[k - 1].id == m.id) refuse(m, "is listed twice");
    // ModuleInstance keeps parameters in a fixed array: no module may have more.
    if (m.parameters.size() > static_cast<std::size_t>(kMaxModuleParameters)) refuse(m, "has too many parameters");
    const bool behaviour = m.kind == ModuleKind::Behaviour;
    if (behaviour ? m.behaviour.run == nullptr : m.condition.check == nullptr)
      refuse(m, behaviour ? "has no behaviour law" : "has no condition law");
    for (std::size_t p = 0; p < m.parameters.size(); ++p) {
      const ParameterSpec& spec = m.parameters[p];
      if (spec.token.empty()) refuse(m, "has an unnamed parameter");
      if (m.parameter_index(spec.token) != static_cast<int>(p)) refuse(m, "names a parameter twice: ", spec.token);
      const bool empty = spec.type == ParameterType::Categorical ? spec.values.empty() : !(spec.min <= spec.max);
      if (empty) refuse(m, "has an empty domain for ", spec.token);
      if (!spec.active_if.empty() && m.parameter_index(spec.active_if) < 0)
        refuse(m, "has a parameter active only for values of one it lacks: ", spec.active_if);
    }
    const ParameterNames& reads = behaviour ? m.behaviour.reads : m.condition.reads;
    std::size_t read = 0;
    m.law_index.fill(0);
    for (std::size_t r = 0; r < reads.size(); ++r) {
      if (reads[r].empty()) continue;
      const int index = m.parameter_index(reads[r]);
      if (index < 0) refuse(m, "has a law that reads a parameter it lacks: ", reads[r]);
      m.law_index[r] = static_cast<std::int8_t>(index);
      ++read;
    }
    if (read != m.parameters.size()) refuse(m, "has a parameter its law does not read");
  }
  return table;
}

}  // namespace sd
