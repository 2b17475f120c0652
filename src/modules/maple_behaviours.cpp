#include "modules/maple_behaviours.hpp"

#include <algorithm>
#include <cmath>

#include "modules/laws.hpp"
#include "simulator/epuck.hpp"

namespace sd::maple {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

}  // namespace

Actuation bounded_wheels_towards(Vec2 v) {
  const double length = v.length();
  if (length == 0.0) return {0.0, 0.0};
  // ComputeWheelsVelocityFromVector of the BT branch: Max(-0.5, Cos(angle)) for the inner wheel
  // (master dropped the bound with RM1.2). The outer wheel is 1, so the speed factor is 12.
  const double c = std::max(kInnerWheelFloor, v.x / length);
  if (v.y > 0.0) return {kMax * c, kMax};
  return {kMax, kMax * c};
}

}  // namespace sd::maple

// The laws of ids 40-45 (laws.hpp); Stop is the shared one.
namespace sd::laws::maple {

namespace {
using P = LawParameters;
using M = BehaviourMemory;
using RM = ReferenceModel;
using sd::maple::bounded_wheels_towards;
}  // namespace

// The BT branch's obstacle test (the base class's ObstacleInFront) needs a reading of 0.5.
const BehaviourLaw exploration{[](P p, M& m, const RM& rm, Rng& rng) {
  return sd::exploration(p[0], sd::maple::kObstacleThreshold * sd::maple::kObstacleThreshold, m, rm, rng);
}, {"rwm"}};
const BehaviourLaw phototaxis{[](P, M&, const RM& rm, Rng&) { return bounded_wheels_towards(phototaxis_vector(rm)); }, {}};
const BehaviourLaw anti_phototaxis{[](P, M&, const RM& rm, Rng&) { return bounded_wheels_towards(anti_phototaxis_vector(rm)); }, {}};
const BehaviourLaw attraction{[](P p, M&, const RM& rm, Rng&) { return bounded_wheels_towards(attraction_vector(rm, p[0])); }, {"att"}};
// The BT branch's Repulsion applies rep once, inside A(rep): -A(rep) - 5 P.
const BehaviourLaw repulsion{[](P p, M&, const RM& rm, Rng&) {
  return bounded_wheels_towards(repulsion_vector(rm, p[0], /*rep_squared=*/false));
}, {"rep"}};

}  // namespace sd::laws::maple
