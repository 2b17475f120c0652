#pragma once
// Shared by the module tests: W(v) restated from ARGoS3-AutoMoDe's AutoMoDeBehaviour (so the
// tests do not reuse the code under test), binomial bands, and generator-state comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "core/geometry.hpp"
#include "core/rng.hpp"
#include "modules/behaviours.hpp"

namespace sd::test {

inline constexpr double kFull = 12.0;

/// W(v) as the spec writes it: theta = UnsignedNormalize(angle of v); 0 < theta < pi turns
/// left (right wheel 12, left 12 cos theta), anything else turns right; 0 -> stop.
inline Actuation spec_wheels(Vec2 v) {
  if (v.x == 0.0 && v.y == 0.0) return {0.0, 0.0, 0};
  const double theta = wrap_unsigned(std::atan2(v.y, v.x));
  if (theta > 0.0 && theta < kPi) return {kFull * std::cos(theta), kFull, 0};
  return {kFull, kFull * std::cos(theta), 0};
}

inline void expect_wheels(const Actuation& actual, const Actuation& expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.left_cm, expected.left_cm, tolerance);
  EXPECT_NEAR(actual.right_cm, expected.right_cm, tolerance);
}

inline ModuleInstance module(int id, std::initializer_list<double> parameters = {}) {
  ModuleInstance m;
  m.id = id;
  std::size_t p = 0;
  for (const double v : parameters) m.parameters[p++] = v;
  return m;
}

inline bool same_rng_state(const Rng& a, const Rng& b) {
  const Rng::State x = a.state(), y = b.state();
  for (int i = 0; i < 4; ++i)
    if (x.s[i] != y.s[i]) return false;
  return x.coarse_left == y.coarse_left && x.coarse_bits == y.coarse_bits;
}

/// |observed - n p| within 5 standard deviations of a binomial count.
inline void expect_binomial(int observed, int n, double p) {
  const double sigma = std::sqrt(n * p * (1.0 - p));
  EXPECT_NEAR(observed, n * p, 5.0 * sigma) << "observed " << observed << " of " << n << ", expected p = " << p;
}

}  // namespace sd::test
