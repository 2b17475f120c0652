#pragma once
// Drawing configurations (irace 3.5 R/generation.R, R/tnorm.R, similarConfigurations in
// R/irace.R). Every draw comes from the one sd::Rng of the design process.
#include <functional>
#include <vector>

#include "core/rng.hpp"
#include "design/model.hpp"
#include "design/parameter_space.hpp"
#include "design/records.hpp"

namespace sd::design {

/// Normal(mean, sd) truncated to [lower, upper]: Robert (1995) rejection with a normal,
/// exponential or uniform proposal depending on the bounds, as R's msm::rtnorm / irace.
double truncated_normal(Rng& rng, double mean, double sd, double lower, double upper);

/// A configuration is acceptable unless this returns false (irace: forbidden expressions and
/// immediately rejected configurations). Retries are bounded as in irace (100).
using Acceptable = std::function<bool(const Configuration&)>;

/// Parameter i drawn uniformly over its domain given the parameters it depends on in `c` (a
/// fixed one: its only value; NA when a bound's parameter is NA).
double sample_uniform_value(const ParameterSpace& space, const Configuration& c, std::size_t i, Rng& rng);
/// Numeric parameter i drawn around `mean` (a normal truncated to its domain, as the model
/// draws it; `sd` in the domain's units, on [0, 1] for a log-scaled one).
double sample_normal_value(const ParameterSpace& space, const Configuration& c, std::size_t i, double mean, double sd,
                           Rng& rng);
/// One configuration, every active parameter uniform over its (current) domain.
Configuration sample_uniform(const ParameterSpace& space, Rng& rng);
std::vector<Configuration> sample_uniform(const ParameterSpace& space, std::size_t n, Rng& rng,
                                          const Acceptable& acceptable = {});

struct SampledConfiguration {
  Configuration config;
  int parent = 0;
};
/// N new configurations from the model: a parent elite drawn by weight, then each active
/// parameter around the parent's value (truncated normal / categorical probabilities).
std::vector<SampledConfiguration> sample_model(const ParameterSpace& space, const std::vector<Elite>& elites,
                                               const ConfigurationStore& store, const Model& model, std::size_t n,
                                               Rng& rng, const Acceptable& acceptable = {});

/// Ids of configurations that have a near-twin in `configs` (same categorical/ordinal values
/// and every numeric value within `threshold` of the domain width, or both NA) — the trigger of
/// irace's soft restart. `configs` in race order (elites first).
std::vector<int> similar_configurations(const ParameterSpace& space, const std::vector<ConfigRecord>& configs,
                                        double threshold);

}  // namespace sd::design
