#include "modules/conditions.hpp"

#include <cmath>

namespace sd {

double neighbours_probability(double xi, double eta, int neighbours) {
  // xi is stored as an integer by AutoMoDe; the difference is signed (the old unsigned
  // wrap-around is a bug we do not reproduce).
  return 1.0 / (1.0 + std::exp(eta * (std::trunc(xi) - static_cast<double>(neighbours))));
}

bool check_condition(const ModuleInstance& c, const ReferenceModel& rm, Rng& rng) {
  const auto& prm = c.parameters;
  switch (c.id) {
    case 10:
      return rm.ground <= 0.1 && rng.bernoulli(prm[0]);
    case 11:
      return rm.ground > 0.1 && rm.ground < 0.95 && rng.bernoulli(prm[0]);
    case 12:
      return rm.ground >= 0.95 && rng.bernoulli(prm[0]);
    case 13:
      return rng.bernoulli(neighbours_probability(prm[0], prm[1], rm.neighbours));
    case 14:
      return rng.bernoulli(1.0 - neighbours_probability(prm[0], prm[1], rm.neighbours));
    case 15:
      return rng.bernoulli(prm[0]);
    default:
      return false;
  }
}

}  // namespace sd
