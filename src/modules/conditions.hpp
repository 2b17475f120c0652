#pragma once
// Condition modules (modules-and-grammar.md §5). A condition is stateless: it looks at the
// reference model and fires with a probability; the Bernoulli draw happens only when its
// precondition holds, as in AutoMoDe.
#include "core/rng.hpp"
#include "modules/catalogue.hpp"
#include "robot/reference_model.hpp"

namespace sd {

bool check_condition(const ModuleInstance& condition, const ReferenceModel& rm, Rng& rng);

/// The logistic of NeighborsCount: 1 / (1 + exp(eta (xi - n))).
double neighbours_probability(double xi, double eta, int neighbours);

}  // namespace sd
