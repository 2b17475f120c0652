#pragma once
// irace's probabilistic model (irace 3.5 R/model.R): one entry per (elite, parameter).
//   categorical: a probability per domain value
//   integer/real: {standard deviation, last active value}; the deviation is in domain units, in
//                 [0,1] log space for log-scale parameters, and a fraction of the current width
//                 for dependent domains
//   ordinal: {standard deviation} in index units
//   fixed parameters: empty
#include <map>
#include <vector>

#include "design/parameter_space.hpp"
#include "design/records.hpp"

namespace sd::design {

struct Model {
  std::map<int, std::vector<std::vector<double>>> entries;  // elite id -> per-parameter entry
  bool has(int id) const { return entries.count(id) != 0; }
  const std::vector<double>& at(int id, std::size_t param) const { return entries.at(id).at(param); }
};

/// Initial standard deviation of a numeric parameter (irace init.model.numeric).
double initial_sd(const Parameter& p);

/// After the first race: uniform probabilities, half-width deviations, elite's own last value.
Model initialise_model(const ParameterSpace& space, const std::vector<Elite>& elites, const ConfigurationStore& store);

/// At the start of iteration j >= 2, for the current elites (a new elite inherits its parent's
/// entry): categorical probabilities move towards the elite's value by (j-1)/N_iter and are capped
/// at 0.2^(1/N_param) in elitist irace; deviations shrink by (1/N_new)^(1/N_param).
Model update_model(const ParameterSpace& space, const std::vector<Elite>& elites, const ConfigurationStore& store,
                   const Model& old, int iteration, int nb_iterations, int nb_new, bool elitist);

/// Soft restart of the model entries `ids` (the caller maps a configuration without an entry to
/// its parent): categorical p <- normalise(0.9 p + 0.1 max p); deviations <-
/// min(sd N^(2/N_param), sd_init (1/N)^(1/N_param)).
void restart_model(Model& model, const ParameterSpace& space, const std::vector<int>& ids, int nb_new);

}  // namespace sd::design
