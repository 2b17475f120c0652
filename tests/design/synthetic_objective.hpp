#pragma once
// A mixed parameter space with a known optimum and a noisy cost over it, for the optimiser's
// tests: C = "c", I = 42, R = 7.5, O = "o4", Q = 0.3 (Q only when C = "c").
#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "design/experiment_runner.hpp"
#include "design/parameter_space.hpp"

namespace sd::design::fixtures {

inline ParameterSpace synthetic_space() {
  ParameterSpace s(2);
  s.add({"C", "--c ", ParamType::Categorical, {"a", "b", "c", "d"}, {}, {}, false, {}});
  s.add({"I", "--i ", ParamType::Integer, {}, Bound::fixed(1), Bound::fixed(100), false, {}});
  s.add({"R", "--r ", ParamType::Real, {}, Bound::fixed(0), Bound::fixed(10), false, {}});
  s.add({"O", "--o ", ParamType::Ordinal, {"o1", "o2", "o3", "o4", "o5"}, {}, {}, false, {}});
  s.add({"Q", "--q ", ParamType::Real, {}, Bound::fixed(0), Bound::fixed(1), false, {{"C", Clause::Op::In, {"c"}, 0}}});
  s.finalize();
  return s;
}

inline double synthetic_cost(const Experiment& e) {
  const auto& v = e.configuration->values;
  const bool good_c = v[0] == 2;
  double cost = good_c ? 0.0 : 1.0;
  cost += 4 * std::pow((v[1] - 42) / 99, 2) + 4 * std::pow((v[2] - 7.5) / 10, 2) + std::pow((v[3] - 3) / 4, 2);
  if (good_c) cost += std::pow(v[4] - 0.3, 2);
  sd::Rng noise(e.seed);  // instance noise shared by all configurations (common random numbers)
  sd::Rng own(e.seed ^ (static_cast<std::uint64_t>(e.configuration_id) * 0x9e3779b97f4a7c15ULL));
  return cost + 0.05 * noise.normal() + 0.02 * own.normal();
}

}  // namespace sd::design::fixtures
