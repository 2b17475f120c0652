#pragma once
// The optimiser's settings for each design method over the modular space. All share irace's
// budget rule, racing (F-test), elitism and persistence; they differ in how later iterations
// draw candidates, so a comparison between them measures that alone.
#include <cstdint>

#include "design/iterated_race.hpp"
#include "design/methods.hpp"
#include "design/parameter_space.hpp"

namespace sd::design {

/// For a design of `method` (automode, random-search or local-search) with `budget` runs over
/// `space`, on `instances` instances. std::invalid_argument for a method without a design space.
IraceOptions method_options(const MethodInfo& method, long long budget, std::uint64_t seed, std::size_t instances,
                            const ParameterSpace& space);

/// The smallest budget `method` accepts for `space`.
long long method_minimum_budget(const MethodInfo& method, const ParameterSpace& space);

}  // namespace sd::design
