#include "modules/behaviours.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/math.hpp"
#include "modules/arlequin.hpp"
#include "modules/laws.hpp"
#include "simulator/epuck.hpp"

namespace sd {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

constexpr std::int32_t kMaxWalkSteps = 100000;  // guards r -> 0 and mu -> 1 (infinite steps)

bool obstacle_in_front(const ReferenceModel& rm) { return rm.proximity.squared_length() >= 0.01 && rm.proximity.x >= 0.0; }

/// Coconut's exploration schemes (DEMI GetHeadingVector): stimulus S pushed away from
/// obstacles; without a stimulus the scheme decides where to go.
Actuation coconut(Vec2 stimulus, double k, LawParameters prm, std::size_t exp_index, BehaviourMemory& m,
                  const ReferenceModel& rm, Rng& rng) {
  Vec2 r = with_fallback(stimulus - rm.proximity * k);
  if (stimulus.squared_length() >= 0.01) return wheels_towards(r);
  const int scheme = static_cast<int>(prm[exp_index]);
  if (scheme == 1) {
    // Ballistic motion with a random turn in place when an obstacle is ahead.
    const double rwm = prm[exp_index + 1];
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
    const double mu = prm[exp_index + 2], rho = prm[exp_index + 3];
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
  const ModuleSpec* spec = find_module(ModuleKind::Behaviour, behaviour.id);
  if (!spec) throw std::invalid_argument("no behaviour module " + std::to_string(behaviour.id) + " in the catalogue");
  if (spec->behaviour.prepare) spec->behaviour.prepare(behaviour.id);
}

Actuation run_behaviour(const ModuleInstance& b, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) {
  const ModuleSpec& spec = module_to_run(ModuleKind::Behaviour, b.id);
  return spec.behaviour.run(spec.law_parameters(b), memory, rm, rng);
}

// The laws the catalogue's entries carry (laws.hpp), each reading its parameters by name.
namespace laws {

namespace {
using P = LawParameters;
using M = BehaviourMemory;
using RM = ReferenceModel;
}  // namespace

const BehaviourLaw stop{[](P, M&, const RM&, Rng&) { return Actuation{0.0, 0.0}; }, {}};
const BehaviourLaw unknown_behaviour{[](P, M&, const RM&, Rng&) -> Actuation {
  throw std::invalid_argument("a behaviour module the catalogue lacks was run");
}, {}};

namespace chocolate {
const BehaviourLaw exploration{[](P p, M& m, const RM& rm, Rng& rng) { return sd::exploration(p[0], kChocolateObstacleSquaredReading, m, rm, rng); }, {"rwm"}};
const BehaviourLaw phototaxis{[](P, M&, const RM& rm, Rng&) { return wheels_towards(phototaxis_vector(rm)); }, {}};
const BehaviourLaw anti_phototaxis{[](P, M&, const RM& rm, Rng&) { return wheels_towards(anti_phototaxis_vector(rm)); }, {}};
const BehaviourLaw attraction{[](P p, M&, const RM& rm, Rng&) { return wheels_towards(attraction_vector(rm, p[0])); }, {"att"}};
const BehaviourLaw repulsion{[](P p, M&, const RM& rm, Rng&) { return wheels_towards(repulsion_vector(rm, p[0], /*rep_squared=*/true)); }, {"rep"}};
}  // namespace chocolate

namespace tuttifrutti {
const BehaviourLaw exploration{[](P p, M& m, const RM& rm, Rng& rng) { return with_led(sd::exploration(p[0], kChocolateObstacleSquaredReading, m, rm, rng), p[1]); }, {"rwm", "cle"}};
const BehaviourLaw stop{[](P p, M&, const RM&, Rng&) { return with_led({0.0, 0.0}, p[0]); }, {"cle"}};
const BehaviourLaw attraction{[](P p, M&, const RM& rm, Rng&) { return with_led(wheels_towards(attraction_vector(rm, p[0])), p[1]); }, {"att", "cle"}};
const BehaviourLaw repulsion{[](P p, M&, const RM& rm, Rng&) { return with_led(wheels_towards(repulsion_vector(rm, p[0], /*rep_squared=*/true)), p[1]); }, {"rep", "cle"}};
// GoToColor: no small-vector fallback.
const BehaviourLaw go_to_color{[](P p, M&, const RM& rm, Rng&) {
  const Vec2 c = color_vector(rm, palette_color(static_cast<int>(p[2])));
  const double length = c.length();
  const Vec2 heading = length > 0.0 ? c * (p[0] / length) : Vec2{p[0], 0.0};
  return with_led(wheels_towards(heading - rm.proximity * 6.0), p[1]);
}, {"vel", "cle", "clr"}};
const BehaviourLaw go_away_color{[](P p, M&, const RM& rm, Rng&) {
  const Vec2 c = color_vector(rm, palette_color(static_cast<int>(p[2])));
  const double length = c.length();
  const Vec2 heading = length > 0.0 ? c * (-p[0] / length) : Vec2{p[0], 0.0};
  return with_led(wheels_towards(heading - rm.proximity * 5.0), p[1]);
}, {"vel", "cle", "clr"}};
}  // namespace tuttifrutti

// Coconut: stimulus and avoidance gain per module, exploration scheme from exp.
namespace coconut {
constexpr ParameterNames kScheme{"exp", "rwm", "mu", "rho"};
const BehaviourLaw exploration{[](P p, M& m, const RM& rm, Rng& rng) { return sd::coconut({}, 1.0, p, 0, m, rm, rng); }, kScheme};
const BehaviourLaw phototaxis{[](P p, M& m, const RM& rm, Rng& rng) { return sd::coconut(rm.light, 5.0, p, 0, m, rm, rng); }, kScheme};
const BehaviourLaw anti_phototaxis{[](P p, M& m, const RM& rm, Rng& rng) { return sd::coconut(-rm.light, 5.0, p, 0, m, rm, rng); }, kScheme};
const BehaviourLaw attraction{[](P p, M& m, const RM& rm, Rng& rng) {
  const double alpha = std::trunc(p[0]);
  return sd::coconut(rm.attraction(alpha) * alpha, 6.0, p, 1, m, rm, rng);
}, {"att", "exp", "rwm", "mu", "rho"}};
const BehaviourLaw repulsion{[](P p, M& m, const RM& rm, Rng& rng) {
  const double alpha = std::trunc(p[0]);
  return sd::coconut(rm.attraction(alpha) * -alpha, 5.0, p, 1, m, rm, rng);
}, {"rep", "exp", "rwm", "mu", "rho"}};
}  // namespace coconut

// Arlequin: the shipped network of the module (arlequin.hpp); no memory, no parameters.
namespace arlequin {
namespace {
template <int Id>
Actuation network_of(P, M&, const RM& rm, Rng&) {
  return sd::arlequin::drive(sd::arlequin::shipped_weights(Id), rm);
}
void load_network(int id) { sd::arlequin::shipped_weights(id); }
}  // namespace
const BehaviourLaw network[6] = {{network_of<50>, {}, load_network}, {network_of<51>, {}, load_network},
                                 {network_of<52>, {}, load_network}, {network_of<53>, {}, load_network},
                                 {network_of<54>, {}, load_network}, {network_of<55>, {}, load_network}};
}  // namespace arlequin

}  // namespace laws

}  // namespace sd
