#pragma once
// The design methods by name: the one list against which a protocol, the experiments database
// and the front ends check a method's name. It sits low (experiments/ reads protocols with it);
// what a method does — its budget rule, how a design of it runs, its convergence and document —
// is app/design_method, whose registry gives every name here an implementation.
#include <array>
#include <string>
#include <string_view>

namespace sd::design {

struct MethodInfo {
  std::string_view name;      // as protocols and the database write it
  std::string_view title;     // as people read it
  bool has_design_space;      // architectures and flavours choose what it searches
};

/// AutoMoDe: Iterated F-Race over modular control software (this folder's optimiser).
inline constexpr MethodInfo kAutoMoDe{"automode", "AutoMoDe", true};
/// EvoStick: neuro-evolution of one network (src/evostick), the thesis' baseline.
inline constexpr MethodInfo kEvoStick{"evostick", "EvoStick", false};
inline constexpr std::array<const MethodInfo*, 2> kMethods{&kAutoMoDe, &kEvoStick};

/// The method of that name, or nullptr.
const MethodInfo* find_method(std::string_view name);
/// "automode or evostick", for messages.
std::string method_names_text();

}  // namespace sd::design
