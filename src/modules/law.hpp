#pragma once
// What a catalogue entry runs: a behaviour's or a condition's law, and the names of the
// parameters it reads. The catalogue resolves each name to the module's parameter index once,
// when the table is built, so a law reads p[k] with no lookup at a control step, and a law
// that names a parameter its module lacks (or a module without a law) fails at start-up.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace sd {

struct Actuation;
struct BehaviourMemory;
struct ReferenceModel;
class Rng;

inline constexpr int kMaxModuleParameters = 6;  // Coconut's Attraction has 5: att, exp, rwm, mu, rho

/// The parameter values of a module instance in the order its law names them.
class LawParameters {
 public:
  LawParameters(const double* values, const std::int8_t* index) : values_(values), index_(index) {}
  double operator[](std::size_t k) const { return values_[index_[k]]; }

 private:
  const double* values_;
  const std::int8_t* index_;
};

/// The parameter names a law reads, in the order it reads them (p[0], p[1], ...).
using ParameterNames = std::array<std::string_view, kMaxModuleParameters>;

struct BehaviourLaw {
  Actuation (*run)(LawParameters p, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) = nullptr;
  ParameterNames reads{};
  /// Called before a run with the module's id, to load what `run` reads at every step (an
  /// Arlequin network), so that no step parses and a missing file fails up front.
  void (*prepare)(int id) = nullptr;
};

struct ConditionLaw {
  /// `neighbours`: the instance's neighbours_table (see conditions.hpp), empty if none.
  bool (*check)(LawParameters p, const ReferenceModel& rm, Rng& rng, std::span<const double> neighbours) = nullptr;
  ParameterNames reads{};
  /// NeighborsCount and InvertedNeighborsCount: p[0] is xi and p[1] eta, and the logistic of
  /// the neighbour count may be tabulated once per run (neighbours_table).
  bool neighbours_logistic = false;
};

}  // namespace sd
