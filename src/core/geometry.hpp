#pragma once
// Plane geometry shared by the simulator, the reference model and the modules.
// Conventions (ARGoS): x forward / east, y left / north, angles counter-clockwise.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/math.hpp"

namespace sd {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Vec2 {
  double x = 0.0, y = 0.0;

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator*(double k) const { return {x * k, y * k}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
  constexpr Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
  constexpr bool operator==(const Vec2&) const = default;

  double length() const { return std::sqrt(x * x + y * y); }  // not hypot: 10x slower, and no overflow here
  constexpr double squared_length() const { return x * x + y * y; }
  /// atan2(y, x); the angle of the zero vector is 0 as in ARGoS.
  double angle() const { return math::atan2(y, x); }
  static Vec2 polar(double length, double angle) {
    const math::SinCos sc = math::sincos(angle);
    return {length * sc.cos, length * sc.sin};
  }
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

/// Distance from p to the segment a-b.
inline double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squared_length();
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + ab * t)).length();
}

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  constexpr Vec2 xy() const { return {x, y}; }
  constexpr bool operator==(const Vec3&) const = default;
};

/// Maps an angle into (-pi, pi] (ARGoS SignedNormalize).
inline double wrap_signed(double a) {
  if (a <= kPi && a > -kPi) return a;  // the common case, without fmod
  if (a > kPi && a <= 3.0 * kPi) return a - kTwoPi;
  if (a <= -kPi && a > -3.0 * kPi) return a + kTwoPi;
  a = std::fmod(a, kTwoPi);
  if (a > kPi) a -= kTwoPi;
  else if (a <= -kPi) a += kTwoPi;
  return a;
}

/// Maps an angle into [0, 2 pi) (ARGoS UnsignedNormalize).
inline double wrap_unsigned(double a) {
  a = std::fmod(a, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  return a;
}

inline double degrees_to_radians(double deg) { return deg * kPi / 180.0; }

}  // namespace sd
