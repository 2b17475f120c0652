#include "modules/conditions.hpp"

#include <cmath>

#include "core/math.hpp"

namespace sd {

double neighbours_probability(double xi, double eta, int neighbours) {
  // xi is stored as an integer by AutoMoDe; the difference is signed (the old unsigned
  // wrap-around is a bug we do not reproduce).
  return 1.0 / (1.0 + math::exp(eta * (std::trunc(xi) - static_cast<double>(neighbours))));
}

std::vector<double> neighbours_table(const ModuleInstance& c, int max_neighbours) {
  switch (c.id) {
    case 13: case 23: case 33: case 43: case 53:  // NeighborsCount
    case 14: case 24: case 34: case 44: case 54:  // InvertedNeighborsCount
      break;
    default:
      return {};
  }
  std::vector<double> table;
  for (int n = 0; n <= max_neighbours; ++n) table.push_back(neighbours_probability(c.parameters[0], c.parameters[1], n));
  return table;
}

namespace {

// A table is sized for one swarm; a count it does not cover is computed rather than assumed
// impossible.
double lookup_neighbours_probability(const ModuleInstance& c, int neighbours, std::span<const double> table) {
  if (neighbours >= 0 && static_cast<std::size_t>(neighbours) < table.size())
    return table[static_cast<std::size_t>(neighbours)];
  return neighbours_probability(c.parameters[0], c.parameters[1], neighbours);
}

}  // namespace

bool check_condition(const ModuleInstance& c, const ReferenceModel& rm, Rng& rng, std::span<const double> table) {
  const auto& prm = c.parameters;
  // Every flavour's conditions 0-5 are Chocolate's. The ids are listed rather than taken
  // modulo 10: conditions are checked for every robot at every step.
  switch (c.id) {
    // TuttiFrutti's RM3.0 (demiurge-epuck-dao branch tuttifrutti) filters the floor as RM1.2.
    case 10: case 20: case 40:  // BlackFloor
      return rm.ground <= 0.1 && rng.bernoulli(prm[0]);
    case 11: case 21: case 41:  // GrayFloor
      return rm.ground > 0.1 && rm.ground < 0.95 && rng.bernoulli(prm[0]);
    case 12: case 22: case 42:  // WhiteFloor
      return rm.ground >= 0.95 && rng.bernoulli(prm[0]);
    // Coconut and Arlequin run on Demiurge's RM3.0, whose floor filter keeps 10 steps.
    case 30: case 50:
      return rm.ground_demiurge <= 0.1 && rng.bernoulli(prm[0]);
    case 31: case 51:
      return rm.ground_demiurge > 0.1 && rm.ground_demiurge < 0.95 && rng.bernoulli(prm[0]);
    case 32: case 52:
      return rm.ground_demiurge >= 0.95 && rng.bernoulli(prm[0]);
    case 13: case 23: case 33: case 43: case 53:  // NeighborsCount
      return rng.bernoulli(lookup_neighbours_probability(c, rm.neighbours, table));
    case 14: case 24: case 34: case 44: case 54:  // InvertedNeighborsCount
      return rng.bernoulli(1.0 - lookup_neighbours_probability(c, rm.neighbours, table));
    case 15: case 25: case 35: case 45: case 55:  // FixedProbability
      return rng.bernoulli(prm[0]);
    case 27: {  // ColorDetection (TuttiFrutti): a blob of colour l at 6 cm or more
      const std::uint32_t rgb = palette_color(static_cast<int>(prm[1]));
      for (const CameraBlob& blob : rm.blobs)
        if (blob.rgb == rgb && blob.distance_cm >= 6.0) return rng.bernoulli(prm[0]);
      return false;
    }
    default:
      return false;
  }
}

}  // namespace sd
