#pragma once
// The catalogue of modules: every behaviour and condition of the five AutoMoDe flavours,
// with its two-digit id (10 x flavour + module digit), name, parameters and law. The grammar
// parser and printer, the design space, the web editor and the controllers all read this one
// table.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "modules/law.hpp"

namespace sd {

enum class Flavour : std::uint8_t { Chocolate = 1, TuttiFrutti = 2, Coconut = 3, Maple = 4, Arlequin = 5 };
enum class ModuleKind : std::uint8_t { Behaviour, Condition };
enum class ParameterType : std::uint8_t { Integer, Real, Categorical };

std::string_view flavour_name(Flavour flavour);
std::optional<Flavour> flavour_from_name(std::string_view name);

struct ParameterSpec {
  std::string token;             // command-line token stem: "rwm" -> --rwm<i>, "p" -> --p<i>x<j>
  ParameterType type;
  double min = 0.0, max = 0.0;   // integer and real domains (inclusive)
  std::vector<double> values;    // categorical domain
  std::string meaning;
  // A parameter may exist only for some values of another parameter of the same module
  // (Coconut: rwm only with exp = 1; mu and rho only with exp = 2). Empty: always.
  std::string active_if;
  std::vector<double> active_values;

  bool accepts(double value) const;
  std::string domain_text() const;
};

/// The inputs a module reads, so that a run simulates only the sensors it needs.
enum Input : std::uint8_t {
  kProximityInput = 1,
  kLightInput = 2,
  kGroundInput = 4,
  kRangeAndBearingInput = 8,
  kCameraInput = 16,
};

/// A module with its parameter values (in the order of its spec's parameters; inactive
/// parameters hold 0).
struct ModuleInstance {
  int id = 0;
  std::array<double, kMaxModuleParameters> parameters{};
  bool operator==(const ModuleInstance&) const = default;
};

struct ModuleSpec {
  int id;                        // two-digit id
  ModuleKind kind;
  std::string name;
  std::vector<ParameterSpec> parameters;
  std::uint8_t inputs = 0;       // Input bits
  BehaviourLaw behaviour;        // behaviours only
  ConditionLaw condition;        // conditions only
  /// Per name the law reads, the index of that parameter (resolved when the table is built).
  std::array<std::int8_t, kMaxModuleParameters> law_index{};

  /// The parameter values of `instance` as this module's law reads them.
  LawParameters law_parameters(const ModuleInstance& instance) const { return {instance.parameters.data(), law_index.data()}; }

  Flavour flavour() const { return static_cast<Flavour>(id / 10); }
  int digit() const { return id % 10; }
  /// Index of the parameter with this token, or -1.
  int parameter_index(std::string_view token) const;
  /// Whether parameter p applies given the values of the others.
  bool parameter_active(std::size_t p, const std::array<double, kMaxModuleParameters>& values) const;
};

/// Every module of a kind, in id order.
std::span<const ModuleSpec> modules(ModuleKind kind);
const ModuleSpec* find_module(ModuleKind kind, int id);
/// The module to run at a control step: found by indexing, not searching. An id the catalogue
/// does not have gives a spec whose law throws std::invalid_argument (never a silent stop);
/// prepare_behaviour and the controllers refuse such ids before a run.
const ModuleSpec& module_to_run(ModuleKind kind, int id);

/// Resolves the parameter names each law reads to indices, and refuses (std::logic_error,
/// naming the module) a table where a module has no law of its kind, a law names a parameter
/// its module lacks, a parameter is not read by the law, or a parameter is unnamed, named
/// twice or has an empty domain. The catalogue passes its tables through this when first used.
std::vector<ModuleSpec> with_resolved_laws(std::vector<ModuleSpec> table);

/// Colour of palette index i (TuttiFrutti, simulation palette): 0 off, 1 green, 2 blue,
/// 3 red, 4 yellow, 5 magenta, 6 cyan; anything else is off.
std::uint32_t palette_color(int index);


}  // namespace sd
