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
  std::string_view summary{}; // one line for a listing
};

/// AutoMoDe: Iterated F-Race over modular control software (this folder's optimiser).
inline constexpr MethodInfo kAutoMoDe{"automode", "AutoMoDe", true,
                                     "Iterated F-Race (irace 3.5): new candidates from a model learnt around the elites"};
/// The same space and racing, new candidates drawn uniformly: the baseline every comparison needs.
inline constexpr MethodInfo kRandomSearch{"random-search", "Random search", true,
                                         "the same races, new candidates drawn uniformly: the baseline"};
/// The same space and racing, new candidates one to three moves from an elite.
inline constexpr MethodInfo kLocalSearch{"local-search", "Local search", true,
                                        "iterated local search: small races of an elite's neighbours (one to three moves)"};
/// EvoStick: neuro-evolution of one network (src/evostick), the thesis' baseline.
inline constexpr MethodInfo kEvoStick{"evostick", "EvoStick", false,
                                     "neuro-evolution of one network (the thesis' baseline; no design space)"};
inline constexpr std::array<const MethodInfo*, 4> kMethods{&kAutoMoDe, &kRandomSearch, &kLocalSearch, &kEvoStick};

/// The method of that name, or nullptr.
const MethodInfo* find_method(std::string_view name);
/// "automode, random-search, local-search or evostick", for messages; only the methods over
/// the modular design space (MethodInfo::has_design_space) when asked.
std::string method_names_text(bool design_space_only = false);

}  // namespace sd::design
