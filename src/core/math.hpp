#pragma once
// Elementary functions that give the same bits on every machine, for a given build.
//
// Why not <cmath>: glibc picks at run time between an FMA and an SSE2 version of sin, cos,
// exp, log, atan2 and others, and the two disagree in the last bit for about 1 argument in
// 1 500 (measured here on 2 million arguments with GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA).
// A run makes tens of such calls per tick and a swarm amplifies a last-bit difference, so the
// same binary scored the same AAC run differently on a CPU without FMA. The functions below use
// only + - * /, sqrt and exact bit operations, which IEEE 754 rounds the same way everywhere
// (the build has -ffp-contract=off, so the compiler fuses no multiply-add either): scores,
// designs and trained networks are reproducible across machines, cluster nodes and glibc
// versions.
//
// Method: Cody and Waite's argument reduction with split constants, then Taylor series summed
// until the truncation error is far below the rounding error (their coefficients are 1/n! and
// 1/(2k+1), written as such). Accuracy: within 2 units in the last place of the correctly
// rounded result (tests/core/math_test.cpp checks it against <cmath>).
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "core/branchless.hpp"

namespace sd::math {

namespace detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The nearest integer (ties to even) for |v| < 2^51: adding 1.5 * 2^52 pushes the fraction
/// out of the significand, and IEEE arithmetic forbids the compiler to fold the two steps.
inline double round_to_int(double v) {
  constexpr double kShift = 0x1.8p52;
  return (v + kShift) - kShift;
}

// pi/2 = A + B + C; A and B have 33 significant bits, so k A and k B are exact for |k| < 2^20.
inline constexpr double kPio2A = 0x1.921fb544p+0;
inline constexpr double kPio2B = 0x1.0b4611a6p-34;
inline constexpr double kPio2C = 0x1.3198a2e037073p-69;
inline constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// pi/2 and pi as a double and the remainder.
inline constexpr double kPio2Hi = 0x1.921fb54442d18p+0, kPio2Lo = 0x1.1a62633145c07p-54;
inline constexpr double kPiHi = 0x1.921fb54442d18p+1, kPiLo = 0x1.1a62633145c07p-53;
// ln 2 = Hi + Lo; Hi has 32 significant bits, so k Hi is exact for every exponent k.
inline constexpr double kLn2Hi = 0x1.62e42ffp-1, kLn2Lo = -0x1.718432a1b0e26p-35;
inline constexpr double kInvLn2 = 0x1.71547652b82fep+0;

constexpr double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }  // exact up to 18!

/// c[0] + z (c[1] + z (c[2] + ...)), summed from the smallest term (Horner's order).
template <std::size_t N>
constexpr double horner(double z, const std::array<double, N>& c) {
  double p = c[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) p = c[i] + z * p;
  return p;
}

/// A series' N coefficients term(0), ..., term(N - 1), computed at compile time.
template <std::size_t N, typename Term>
constexpr std::array<double, N> series(Term term) {
  std::array<double, N> c{};
  for (std::size_t k = 0; k < N; ++k) c[k] = term(static_cast<int>(k));
  return c;
}
/// -1, +1, -1, ...: the signs of the sin, cos and atan series after their first term.
constexpr double alternating(int k) { return k % 2 == 0 ? -1.0 : 1.0; }

/// sin r = r + r z (-1/3! + z/5! - ... + z^7/17!) with z = r^2, for |r| <= pi/4: the next
/// term is below 1e-19.
inline double sin_kernel(double r) {
  constexpr auto kSeries = series<8>([](int k) { return alternating(k) / factorial(3 + 2 * k); });
  const double z = r * r;
  return r + r * (z * horner(z, kSeries));
}

/// cos r = 1 + z (-1/2! + z/4! - ... + z^7/16!), for |r| <= pi/4: the next term is below 3e-18.
inline double cos_kernel(double r) {
  constexpr auto kSeries = series<8>([](int k) { return alternating(k) / factorial(2 + 2 * k); });
  const double z = r * r;
  return 1.0 + z * horner(z, kSeries);
}

/// atan(j/8) = kAtanHi[j] + kAtanLo[j] (computed with mpmath at 300 bits).
inline constexpr double kAtanHi[9] = {0.0,
                                      0x1.fd5ba9aac2f6ep-4,
                                      0x1.f5b75f92c80ddp-3,
                                      0x1.6f61941e4def1p-2,
                                      0x1.dac670561bb4fp-2,
                                      0x1.1e00babdefeb4p-1,
                                      0x1.4978fa3269ee1p-1,
                                      0x1.700a7c5784634p-1,
                                      0x1.921fb54442d18p-1};
inline constexpr double kAtanLo[9] = {0.0,
                                      -0x1.cd37686760c17p-59,
                                      0x1.8ab6e3cf7afbdp-57,
                                      -0x1.c63aae6f6e918p-56,
                                      0x1.a2b7f222f65e2p-56,
                                      -0x1.928df287a668fp-58,
                                      0x1.2419a87f2a458p-56,
                                      -0x1.8c34d25aadef6p-56,
                                      0x1.1a62633145c07p-55};

/// atan a for 0 <= a <= 1 as hi + lo: atan a = atan c + atan t with c = j/8 the nearest
/// eighth and t = (a - c) / (1 + a c), |t| <= 1/16, whose series up to t^15/15 leaves < 1e-20.
struct Split {
  double hi, lo;
};
inline Split atan_unit(double a) {
  const double j = round_to_int(a * 8.0);
  const double c = j * 0.125;
  const double t = (a - c) / (1.0 + a * c);  // a - c is exact (Sterbenz)
  // atan t = t + t z (-1/3 + z/5 - ... - z^6/15) with z = t^2.
  constexpr auto kSeries = series<7>([](int k) { return alternating(k) / (3.0 + 2 * k); });
  const double z = t * t;
  const double p = horner(z, kSeries);
  const auto k = static_cast<std::size_t>(j);
  return {kAtanHi[k], kAtanLo[k] + (t + t * (z * p))};
}

}  // namespace detail

struct SinCos {
  double sin, cos;
};

/// sin x and cos x together. Accurate for |x| < 2^19 pi; from 2^50 on (where one unit in the
/// last place of x is a quarter of a radian: no angle is meant) and for infinities and
/// NaN: NaN.
inline SinCos sincos(double x) {
  using namespace detail;
  if (!(std::abs(x) < 0x1p50)) return {kNaN, kNaN};
  if (std::abs(x) < 0x1p-27) return {x, 1.0};  // x - x^3/6 and 1 - x^2/2 round to these; keeps sin(-0) = -0
  const double k = round_to_int(x * kTwoOverPi);
  const double r = ((x - k * kPio2A) - k * kPio2B) - k * kPio2C;
  const double s = sin_kernel(r), c = cos_kernel(r);
  // Quadrant q: (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s). Headings turn both ways, so q
  // is a coin toss: chosen without jumps.
  const auto q = static_cast<std::uint64_t>(static_cast<std::int64_t>(k));
  const bool odd = (q & 1) != 0;
  return {negate_if(((q >> 1) & 1) != 0, select(odd, c, s)), negate_if((((q + 1) >> 1) & 1) != 0, select(odd, s, c))};
}
inline double sin(double x) { return sincos(x).sin; }
inline double cos(double x) { return sincos(x).cos; }
inline double tan(double x) {
  const SinCos sc = sincos(x);
  return sc.sin / sc.cos;
}

/// e^x; overflows to infinity above ~709.78 and underflows through the subnormals to 0.
inline double exp(double x) {
  using namespace detail;
  if (x != x) return x;
  if (x > 709.8) return kInf;
  if (x < -745.2) return 0.0;
  const double k = round_to_int(x * kInvLn2);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;  // |r| <= ln2 / 2
  // e^r - 1 up to r^13/13!; the next term is below 5e-18. The polynomial in r after r^2 is
  // summed in Estrin's order, pairs first, so that its steps do not wait on one another.
  constexpr auto c = [](int n) { return 1.0 / factorial(n); };
  const double r2 = r * r, r4 = r2 * r2;
  const double p01 = (c(2) + c(3) * r) + r2 * (c(4) + c(5) * r);
  const double p23 = (c(6) + c(7) * r) + r2 * (c(8) + c(9) * r);
  const double p45 = (c(10) + c(11) * r) + r2 * (c(12) + c(13) * r);
  const double p = p01 + r4 * (p23 + r4 * p45);
  const double y = 1.0 + (r + r2 * p);
  // y 2^k: one exact scaling while 2^k is a normal number, two (the second rounds once into
  // the subnormals, or overflows) beyond.
  const auto n = static_cast<std::int64_t>(k);
  auto two_to = [](std::int64_t e) { return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52); };
  if (n >= -1022 && n <= 1023) return y * two_to(n);
  if (n > 1023) return y * two_to(1023) * two_to(n - 1023);
  return y * two_to(n + 1000) * two_to(-1000);
}

/// Natural logarithm; log 0 = -infinity, NaN for negative arguments and NaN.
inline double log(double x) {
  using namespace detail;
  if (!(x > 0.0)) return x == 0.0 ? -kInf : kNaN;
  if (x == kInf) return x;
  std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  std::int64_t e = 0;
  if (bits < (std::uint64_t{1} << 52)) {  // subnormal: scale into the normal range first
    bits = std::bit_cast<std::uint64_t>(x * 0x1p54);
    e = -54;
  }
  // x = 2^e m with m in [sqrt(1/2), sqrt(2)): the significand is halved when it is above
  // sqrt 2, decided on its bits (no jump: a uniform draw's significand is a coin toss here).
  constexpr std::uint64_t kFraction = (std::uint64_t{1} << 52) - 1;
  constexpr std::uint64_t kSqrt2Fraction = 0x6a09e667f3bcdULL;  // fraction bits of sqrt 2
  const std::uint64_t above = (bits & kFraction) > kSqrt2Fraction ? 1 : 0;
  e += static_cast<std::int64_t>(bits >> 52) - 1023 + static_cast<std::int64_t>(above);
  const double m = std::bit_cast<double>((bits & kFraction) | ((1023 - above) << 52));
  // log m = 2 atanh s with s = (m - 1) / (m + 1), |s| <= 0.172: 2s + 2s^3/3 + ... up to
  // 2s^21/21; the next term is below 1e-18 of the sum.
  const double f = m - 1.0;  // exact
  const double s = f / (2.0 + f);
  const double z = s * s;
  constexpr auto kSeries = series<10>([](int k) { return 2.0 / (3.0 + 2 * k); });  // 2/3, ..., 2/21
  const double q = horner(z, kSeries);
  const double log_m = 2.0 * s + s * (z * q);
  const auto ed = static_cast<double>(e);
  return ed * kLn2Hi + (log_m + ed * kLn2Lo);
}

/// x^y for x > 0, as e^(y log x) (relative error about |y log x| units of 1e-16); NaN for x <= 0.
inline double pow(double x, double y) {
  if (!(x > 0.0)) return detail::kNaN;
  return exp(y * log(x));
}

/// Arc tangent, in [-pi/2, pi/2].
inline double atan(double x) {
  using namespace detail;
  if (x != x) return x;
  const double a = std::abs(x);
  double v;
  if (a <= 1.0) {
    const Split s = atan_unit(a);
    v = s.hi + s.lo;
  } else {  // atan a = pi/2 - atan(1/a)
    const Split s = atan_unit(1.0 / a);
    v = (kPio2Hi - s.hi) + (kPio2Lo - s.lo);
  }
  return negate_if(std::signbit(x), v);
}

/// The angle of (x, y), in [-pi, pi], with C's conventions for zeros and infinities
/// (atan2(0, 0) = 0, as ARGoS has it for the zero vector).
inline double atan2(double y, double x) {
  using namespace detail;
  if (x != x || y != y) return x + y;
  const double ax = std::abs(x), ay = std::abs(y);
  const bool y_negative = std::signbit(y);
  if (!(ax > 0.0 && ay > 0.0 && ax < kInf && ay < kInf)) {  // zeros and infinities: rare
    double v;
    // NOLINTBEGIN(bugprone-branch-clone): fdlibm's special cases, listed as it lists them
    if (ay == 0.0) v = std::signbit(x) ? kPiHi : 0.0;
    else if (ax == 0.0) v = kPio2Hi;
    else if (ax == kInf && ay == kInf) v = std::signbit(x) ? 3.0 * kPiHi / 4.0 : kPiHi / 4.0;
    else if (ax == kInf) v = std::signbit(x) ? kPiHi : 0.0;
    else v = kPio2Hi;
    // NOLINTEND(bugprone-branch-clone)
    return negate_if(y_negative, v);
  }
  // The octant's angle in [0, pi/4] from the smaller over the larger coordinate, then moved
  // to the quadrant without jumps (the octant of a bearing is a coin toss).
  const bool steep = ay > ax;
  const Split s = atan_unit(select(steep, ax, ay) / select(steep, ay, ax));
  double hi = select(steep, kPio2Hi - s.hi, s.hi);
  double lo = select(steep, kPio2Lo - s.lo, s.lo);
  const bool behind = std::signbit(x);
  hi = select(behind, kPiHi - hi, hi);
  lo = select(behind, kPiLo - lo, lo);
  return negate_if(y_negative, hi + lo);
}

}  // namespace sd::math
