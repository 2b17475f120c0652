#pragma once
// Conditionals without jumps, for the simulator's hot loops. Inside a cluster of robots many
// conditions (is this reading below 0, does this ray meet that body) are coin tosses, and a
// mispredicted jump costs more than computing both sides. GCC turns a conditional
// expression between doubles into a jump whenever signed zeros or NaNs make minsd/maxsd
// inexact, so these are written so that no jump is possible. Each returns exactly what the
// plain conditional would.
#include <bit>
#include <cmath>
#include <cstdint>

namespace sd {

/// `condition ? a : b`, through bit masks.
inline double select(bool condition, double a, double b) {
  const std::uint64_t mask = -static_cast<std::uint64_t>(condition);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

/// -v when `negate`, else v: flips the sign bit (exact, NaN and zeros included).
inline double negate_if(bool negate, double v) {
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) ^ (static_cast<std::uint64_t>(negate) << 63));
}

/// max(v, 0): (v + |v|) / 2 is exact for every v below DBL_MAX / 2 (2v must not overflow).
inline double max0(double v) { return (v + std::abs(v)) * 0.5; }

/// v clamped to [0, 1] (minsd does the upper bound).
inline double clamp01(double v) {
  v = max0(v);
  return v < 1.0 ? v : 1.0;
}

}  // namespace sd
