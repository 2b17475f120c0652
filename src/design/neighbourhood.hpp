#pragma once
// The moves of local search over the modular design space. In irace's formulation every
// structural choice is a parameter (NumStates, a state's behaviour, a transition's condition and
// target, a tree's branches), so one move — change one active parameter, then redraw whatever
// that change switched on — covers "change a module", "change a parameter" and "add or remove a
// state, transition or branch" alike, and always yields a valid configuration of the space.
//
//   Configuration next = neighbour(space, incumbent, rng, 1);
//   auto fresh = sample_neighbours(space, elites, store, 8, rng, acceptable);
#include <vector>

#include "core/rng.hpp"
#include "design/parameter_space.hpp"
#include "design/records.hpp"
#include "design/sampling.hpp"

namespace sd::design {

/// The parameters a move may change in `c`: active and with more than one value.
std::vector<std::size_t> movable_parameters(const ParameterSpace& space, const Configuration& c);

/// `c` after one move of parameter i (movable in `c`): see neighbour().
Configuration moved(const ParameterSpace& space, Configuration c, std::size_t i, Rng& rng);

/// `c` after `moves` moves, each of a movable parameter drawn uniformly: each changes one movable parameter to another value (a category
/// drawn among the others; a number drawn uniformly or, half the time, around its value with a
/// tenth of its domain as deviation), then redraws uniformly each parameter the change
/// activated or pushed outside its domain and clears those it deactivated.
Configuration neighbour(const ParameterSpace& space, Configuration c, Rng& rng, int moves);

/// N neighbours of the elites: a parent drawn by the elites' weights, then 1 move, 2 with
/// probability 1/2, 3 with 1/4 (a perturbation that lets the search leave a local optimum
/// without a state of its own to resume).
std::vector<SampledConfiguration> sample_neighbours(const ParameterSpace& space, const std::vector<Elite>& elites,
                                                    const ConfigurationStore& store, std::size_t n, Rng& rng,
                                                    const Acceptable& acceptable = {});

}  // namespace sd::design
