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
  if (c.id == 27) {  // ColorDetection (TuttiFrutti): a blob of colour l at 6 cm or more
    const std::uint32_t rgb = palette_color(static_cast<int>(prm[1]));
    for (const CameraBlob& blob : rm.blobs)
      if (blob.rgb == rgb && blob.distance_cm >= 6.0) return rng.bernoulli(prm[0]);
    return false;
  }
  // Every flavour's conditions 0-5 are Chocolate's.
  switch (c.id % 10) {
    case 0:
      return rm.ground <= 0.1 && rng.bernoulli(prm[0]);
    case 1:
      return rm.ground > 0.1 && rm.ground < 0.95 && rng.bernoulli(prm[0]);
    case 2:
      return rm.ground >= 0.95 && rng.bernoulli(prm[0]);
    case 3:
      return rng.bernoulli(neighbours_probability(prm[0], prm[1], rm.neighbours));
    case 4:
      return rng.bernoulli(1.0 - neighbours_probability(prm[0], prm[1], rm.neighbours));
    case 5:
      return rng.bernoulli(prm[0]);
    default:
      return false;
  }
}

}  // namespace sd
