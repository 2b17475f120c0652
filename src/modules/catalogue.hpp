#pragma once
// The catalogue of modules: every behaviour and condition of the five AutoMoDe flavours,
// with its two-digit id (10 x flavour + module digit), name and parameters. The grammar
// parser and printer, the design space and the web editor all read this one table.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

inline constexpr int kMaxModuleParameters = 6;  // Coconut's Attraction has 5: att, exp, rwm, mu, rho

/// The inputs a module reads, so that a run simulates only the sensors it needs.
enum Input : std::uint8_t {
  kProximityInput = 1,
  kLightInput = 2,
  kGroundInput = 4,
  kRangeAndBearingInput = 8,
  kCameraInput = 16,
};

struct ModuleSpec {
  int id;                        // two-digit id
  ModuleKind kind;
  std::string name;
  std::vector<ParameterSpec> parameters;
  std::uint8_t inputs = 0;       // Input bits

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

/// Colour of palette index i (TuttiFrutti, simulation palette): 0 off, 1 green, 2 blue,
/// 3 red, 4 yellow, 5 magenta, 6 cyan; anything else is off.
std::uint32_t palette_color(int index);

/// A module with its parameter values (in the order of its spec's parameters; inactive
/// parameters hold 0).
struct ModuleInstance {
  int id = 0;
  std::array<double, kMaxModuleParameters> parameters{};
  bool operator==(const ModuleInstance&) const = default;
};

}  // namespace sd
