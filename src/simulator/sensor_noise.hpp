#pragma once
// The e-puck's uniform sensor noise, shared by the proximity, light and ground sensors, and
// the per-robot reading gains of a pseudo-reality.
#include <array>
#include <cstddef>

#include "core/math.hpp"
#include "core/rng.hpp"

namespace sd {

/// Adds uniform noise in [-level, level) to each reading and clamps it to [0, 1] (the
/// e-puck's proximity, light and ground sensors), drawn as one batch.
template <std::size_t N>
void add_uniform_noise(std::array<double, N>& readings, double level, Rng& rng) {
  std::array<double, N> noise;
  rng.coarse_uniforms(-level, level, noise.data(), static_cast<int>(N));
  for (std::size_t k = 0; k < N; ++k) readings[k] = clamp01(readings[k] + noise[k]);
}

/// A robot's own sensor gain (a per-robot deviation), applied before the noise; the noise's
/// clamp keeps the reading in [0, 1].
template <std::size_t N>
void scale_readings(std::array<double, N>& readings, double gain) {
  for (double& v : readings) v *= gain;
}

}  // namespace sd
