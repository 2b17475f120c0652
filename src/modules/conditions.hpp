#pragma once
// Condition modules (ARGoS3-AutoMoDe's AutoMoDeCondition*). A condition is stateless: it looks
// at the reference model and fires with a probability; the Bernoulli draw happens only when its
// precondition holds, as in AutoMoDe.
#include <span>
#include <vector>

#include "core/rng.hpp"
#include "modules/catalogue.hpp"
#include "robot/reference_model.hpp"

namespace sd {

/// `table`: the condition's neighbours_table, looked up for the neighbour counts it covers; any
/// other count, or an empty table, computes the probability.
bool check_condition(const ModuleInstance& condition, const ReferenceModel& rm, Rng& rng,
                     std::span<const double> table = {});

/// The logistic of NeighborsCount: 1 / (1 + exp(eta (xi - n))).
double neighbours_probability(double xi, double eta, int neighbours);

/// neighbours_probability of a NeighborsCount or InvertedNeighborsCount condition for 0 ..
/// max_neighbours neighbours; empty for any other condition. Conditions are checked for every
/// robot at every step, and a lookup costs far less than the exp; the values are the
/// function's own, so a run is the same with or without the table.
std::vector<double> neighbours_table(const ModuleInstance& condition, int max_neighbours);

}  // namespace sd
