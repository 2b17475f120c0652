#include "design/method_options.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sd::design {

namespace {

/// Local search races the elites' neighbours in small races, many of them: about 40 over the
/// budget, none below 300 runs.
constexpr long long kLocalSearchRaces = 40;
constexpr long long kMinimumRace = 300;

}  // namespace

IraceOptions method_options(const MethodInfo& method, long long budget, std::uint64_t seed, std::size_t instances,
                            const ParameterSpace& /*space*/) {
  if (!method.has_design_space) throw std::invalid_argument(std::string(method.name) + " has no modular design space");
  IraceOptions o;
  o.max_experiments = budget;
  o.seed = seed;
  o.n_instances = instances;
  if (&method == &kRandomSearch) {
    o.sampler = Sampler::Uniform;
  } else if (&method == &kLocalSearch) {
    o.sampler = Sampler::Neighbourhood;
    o.soft_restart = false;  // it restarts the model, which local search does not use
    o.nb_iterations = 0;     // as many races as the budget pays for
    // irace's rule sizes each race: the elites and as many neighbours as its budget pays for,
    // fewer as the elites' instances pile up (a newcomer must face them on all of them).
    o.nb_experiments_per_iteration = std::max(budget / kLocalSearchRaces, kMinimumRace);
  }
  return o;
}

long long method_minimum_budget(const MethodInfo& method, const ParameterSpace& space) {
  const IraceOptions o = method_options(method, 1, 0, 1, space);
  const int n = default_nb_iterations(space.nb_variable());
  const long long irace_minimum = minimum_budget(o, n, n);
  return &method == &kLocalSearch ? std::max(irace_minimum, o.nb_experiments_per_iteration * 2) : irace_minimum;
}

}  // namespace sd::design
