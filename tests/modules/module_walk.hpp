#pragma once
// Runs one catalogue module on a small swarm for a few control steps and folds everything it
// did (wheels, LEDs, fired or not, the generator's state) into one number. Uses only the
// modules' public interface, so the same walk can be run against another build to compare.
#include <bit>
#include <cstdint>

#include "core/rng.hpp"
#include "modules/behaviours.hpp"
#include "modules/catalogue.hpp"
#include "modules/conditions.hpp"
#include "robot/reference_model.hpp"
#include "simulator/swarm.hpp"

namespace sd::test {

/// Parameter values in each parameter's domain; `variant` walks the categorical values (so
/// Coconut's exp takes 0, 1 and 2) and the numeric domains from min to max. Parameters
/// inactive for these values hold 0, as a parsed instance has them.
inline ModuleInstance walk_instance(const ModuleSpec& spec, int variant) {
  ModuleInstance m;
  m.id = spec.id;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    const ParameterSpec& ps = spec.parameters[p];
    if (ps.type == ParameterType::Categorical) {
      m.parameters[p] = ps.values[static_cast<std::size_t>(variant) % ps.values.size()];
    } else {
      const double f = (variant % 3) / 2.0;
      const double v = ps.min + f * (ps.max - ps.min);
      m.parameters[p] = ps.type == ParameterType::Integer ? std::floor(v) : v;
    }
  }
  for (std::size_t p = 0; p < spec.parameters.size(); ++p)
    if (!spec.parameter_active(p, m.parameters)) m.parameters[p] = 0.0;
  return m;
}

/// Fresh raw readings for every robot: what the sensors would have written this tick.
inline void fake_sensing(SwarmState& s, Rng& world) {
  constexpr std::uint32_t kColours[] = {0x00ff00, 0x0000ff, 0xff0000, 0xffff00, 0xff00ff, 0x00ffff};
  for (int i = 0; i < s.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    for (double& v : s.proximity[r]) v = world.uniform() < 0.7 ? 0.0 : world.uniform();
    for (double& v : s.light[r]) v = world.uniform();
    const double floor_gray = world.uniform() < 0.4 ? 0.0 : world.uniform() < 0.5 ? 1.0 : 0.5;
    for (double& v : s.ground[r]) v = floor_gray;
    s.rab_count[r] = static_cast<std::uint16_t>(world.below(static_cast<std::uint32_t>(s.size)));
    for (std::uint16_t k = 0; k < s.rab_count[r]; ++k)
      s.rab[r * s.rab_stride() + k] = {world.uniform(0.0, 70.0), Vec2::polar(1.0, world.uniform(-3.0, 3.0)), k};
    s.blob_count[r] = static_cast<std::uint16_t>(world.below(static_cast<std::uint32_t>(s.blobs_per_robot) + 1));
    for (std::uint16_t k = 0; k < s.blob_count[r]; ++k)
      s.blobs[r * static_cast<std::size_t>(s.blobs_per_robot) + k] = {kColours[world.below(6)], Vec2::polar(1.0, world.uniform(-3.0, 3.0)),
                                                                       world.uniform(0.0, 40.0)};
  }
}

inline std::uint64_t mix(std::uint64_t h, std::uint64_t v) { return (h ^ v) * 0x100000001b3ull + (h >> 29); }
inline std::uint64_t mix(std::uint64_t h, double v) { return mix(h, std::bit_cast<std::uint64_t>(v)); }

/// Every robot of a 5-robot swarm runs `instance` for `steps` control steps.
inline std::uint64_t walk_fingerprint(ModuleKind kind, const ModuleInstance& instance, std::uint64_t seed, int steps = 40) {
  constexpr int kRobots = 5;
  SwarmState s;
  s.resize(kRobots, 2);
  std::vector<ReferenceModel> rm(kRobots);
  std::vector<BehaviourMemory> memory(kRobots);
  for (auto& r : rm) r.reset();
  Rng world(seed), rng(seed + 1);
  const std::vector<double> table = kind == ModuleKind::Condition ? neighbours_table(instance, kRobots - 1) : std::vector<double>{};
  if (kind == ModuleKind::Behaviour) prepare_behaviour(instance);
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (int t = 0; t < steps; ++t) {
    fake_sensing(s, world);
    for (int i = 0; i < kRobots; ++i) {
      const auto r = static_cast<std::size_t>(i);
      rm[r].update(s, i);
      if (kind == ModuleKind::Behaviour) {
        const Actuation a = run_behaviour(instance, memory[r], rm[r], rng);
        h = mix(mix(mix(h, a.left_cm), a.right_cm), static_cast<std::uint64_t>(a.led));
      } else {
        h = mix(h, static_cast<std::uint64_t>(check_condition(instance, rm[r], rng, table)));
      }
    }
  }
  const Rng::State end = rng.state();
  for (int k = 0; k < 4; ++k) h = mix(h, end.s[k]);
  return h;
}

}  // namespace sd::test
