#include "modules/behaviours.hpp"

#include <cmath>

#include "core/math.hpp"
#include "modules/arlequin.hpp"
#include "modules/maple_behaviours.hpp"
#include "simulator/epuck.hpp"

namespace sd {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

constexpr std::int32_t kMaxWalkSteps = 100000;  // guards r -> 0 and mu -> 1 (infinite steps)

bool obstacle_in_front(const ReferenceModel& rm) { return rm.proximity.squared_length() >= 0.01 && rm.proximity.x >= 0.0; }

/// Coconut's exploration schemes (DEMI GetHeadingVector): stimulus S pushed away from
/// obstacles; without a stimulus the scheme decides where to go.
Actuation coconut(Vec2 stimulus, double k, const ModuleInstance& b, int exp_index, BehaviourMemory& m,
                  const ReferenceModel& rm, Rng& rng) {
  Vec2 r = with_fallback(stimulus - rm.proximity * k);
  if (stimulus.squared_length() >= 0.01) return wheels_towards(r);
  const auto& prm = b.parameters;
  const int scheme = static_cast<int>(prm[static_cast<std::size_t>(exp_index)]);
  if (scheme == 1) {
    // Ballistic motion with a random turn in place when an obstacle is ahead.
    const double rwm = prm[static_cast<std::size_t>(exp_index + 1)];
    if (m.walk_steps <= 0) {
      if (obstacle_in_front(rm)) {
        m.walk_steps = static_cast<std::int32_t>(rng.uniform_int(0, static_cast<std::uint32_t>(rwm)));
        m.walk_angle = rm.proximity.y < 0.0 ? kPi - 1e-4 : kPi + 1e-4;  // spin left / right
      } else {
        m.walk_angle = 0.0;
      }
    } else {
      m.walk_steps -= 1;
    }
    r = Vec2::polar(1.0, m.walk_angle);
  } else if (scheme == 2) {
    // Random walk: power-law step lengths (exponent mu), wrapped-Cauchy turns (rho); one
    // uniform draw feeds both, as in DEMI.
    const double mu = prm[static_cast<std::size_t>(exp_index + 2)], rho = prm[static_cast<std::size_t>(exp_index + 3)];
    if (m.walk_steps <= 0) {
      const double u = rng.uniform();
      const double length = mu > 1.0 && u > 0.0 ? math::pow(u, 1.0 / (1.0 - mu)) : INFINITY;
      m.walk_steps = length < kMaxWalkSteps ? static_cast<std::int32_t>(std::ceil(length + 0.5)) : kMaxWalkSteps;
      m.walk_angle = wrap_signed(2.0 * math::atan((1.0 - rho) / (1.0 + rho) * math::tan(kPi * (u - 0.5))));
    } else {
      m.walk_steps -= 1;
    }
    if (obstacle_in_front(rm)) {
      const double phi = rm.proximity.angle();
      const double away = phi >= 0.0 ? phi - kPi : phi + kPi;
      m.walk_angle = (m.walk_angle + away) / 2.0;  // plain average, as in DEMI
    }
    r = Vec2::polar(1.0, m.walk_angle);
  }
  return wheels_towards(r);
}

Actuation with_led(Actuation a, double palette_index) {
  a.led = palette_color(static_cast<int>(palette_index));
  return a;
}

}  // namespace

Vec2 color_vector(const ReferenceModel& rm, std::uint32_t rgb) {
  Vec2 sum;
  for (const CameraBlob& blob : rm.blobs)
    if (blob.rgb == rgb && blob.distance_cm >= 6.0) sum += blob.direction * (1.0 / (blob.distance_cm + 1.0));
  return sum;
}

Actuation wheels_towards(Vec2 v) {
  const double length = v.length();
  if (length == 0.0) return {0.0, 0.0};
  const double c = v.x / length;
  if (v.y > 0.0) return {kMax * c, kMax};
  return {kMax, kMax * c};
}

Actuation exploration(double rwm, double obstacle_squared_reading, BehaviourMemory& m, const ReferenceModel& rm, Rng& rng) {
  if (!m.turning) {
    // The step that sees an obstacle still drives forward; the turn starts next step.
    const Vec2 p = rm.proximity;
    if (p.squared_length() >= obstacle_squared_reading && p.x >= 0.0) {
      m.turning = true;
      m.turn_steps = static_cast<std::int32_t>(rng.uniform_int(0, static_cast<std::uint32_t>(rwm)));
      m.turn_left = p.y < 0.0;  // obstacle on the right: turn left
    }
    return {epuck::kMaxWheelSpeedCm, epuck::kMaxWheelSpeedCm};
  }
  m.turn_steps -= 1;
  if (m.turn_steps <= 0) m.turning = false;
  constexpr double v = epuck::kMaxWheelSpeedCm;
  return m.turn_left ? Actuation{-v, v} : Actuation{v, -v};
}

void reset_behaviour(BehaviourMemory& memory) { memory = BehaviourMemory{}; }

void prepare_behaviour(const ModuleInstance& behaviour) {
  if (arlequin::is_module(behaviour.id)) arlequin::shipped_weights(behaviour.id);
}

Actuation run_behaviour(const ModuleInstance& b, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) {
  const auto& prm = b.parameters;
  switch (b.id) {
    // Chocolate (parameters: rwm | att | rep).
    case 10:
      return exploration(prm[0], kChocolateObstacleSquaredReading, memory, rm, rng);
    case 11:
      return {0.0, 0.0};
    case 12:
      return wheels_towards(phototaxis_vector(rm));
    case 13:
      return wheels_towards(anti_phototaxis_vector(rm));
    case 14:
      return wheels_towards(attraction_vector(rm, prm[0]));
    case 15:
      return wheels_towards(repulsion_vector(rm, prm[0], /*rep_squared=*/true));
    // TuttiFrutti: the Chocolate laws plus the LED colour cle (last parameter but clr).
    case 20:
      return with_led(exploration(prm[0], kChocolateObstacleSquaredReading, memory, rm, rng), prm[1]);
    case 21:
      return with_led({0.0, 0.0}, prm[0]);
    case 24:
      return with_led(wheels_towards(attraction_vector(rm, prm[0])), prm[1]);
    case 25:
      return with_led(wheels_towards(repulsion_vector(rm, prm[0], /*rep_squared=*/true)), prm[1]);
    case 28: {  // GoToColor: vel, cle, clr; no small-vector fallback
      const Vec2 c = color_vector(rm, palette_color(static_cast<int>(prm[2])));
      const double length = c.length();
      const Vec2 heading = length > 0.0 ? c * (prm[0] / length) : Vec2{prm[0], 0.0};
      return with_led(wheels_towards(heading - rm.proximity * 6.0), prm[1]);
    }
    case 29: {  // GoAwayColor
      const Vec2 c = color_vector(rm, palette_color(static_cast<int>(prm[2])));
      const double length = c.length();
      const Vec2 heading = length > 0.0 ? c * (-prm[0] / length) : Vec2{prm[0], 0.0};
      return with_led(wheels_towards(heading - rm.proximity * 5.0), prm[1]);
    }
    // Coconut: stimulus and avoidance gain per module, exploration scheme from exp.
    case 30:
      return coconut({}, 1.0, b, 0, memory, rm, rng);
    case 31:
      return {0.0, 0.0};
    case 32:
      return coconut(rm.light, 5.0, b, 0, memory, rm, rng);
    case 33:
      return coconut(-rm.light, 5.0, b, 0, memory, rm, rng);
    case 34: {
      const double alpha = std::trunc(prm[0]);
      return coconut(rm.attraction(alpha) * alpha, 6.0, b, 1, memory, rm, rng);
    }
    case 35: {
      const double alpha = std::trunc(prm[0]);
      return coconut(rm.attraction(alpha) * -alpha, 5.0, b, 1, memory, rm, rng);
    }
    // Maple: the BT branch's own laws (maple_behaviours.hpp).
    case 40: case 41: case 42: case 43: case 44: case 45:
      return maple::run_behaviour(b, memory, rm, rng);
    // Arlequin: the shipped network of the module (arlequin.hpp); no memory, no parameters.
    case 50:
    case 51:
    case 52:
    case 53:
    case 54:
    case 55:
      return arlequin::drive(arlequin::shipped_weights(b.id), rm);
    default:
      return {0.0, 0.0};
  }
}

}  // namespace sd
