#pragma once
// The single source of randomness of one evaluation. Every draw of a simulation
// (placement, sensor and wheel noise, module decisions, objective sampling) comes from
// one Rng seeded by the evaluation's seed, so (mission, control software, seed) -> score
// is a pure function whatever the thread it runs on.
//
// Generator: xoshiro256** (Blackman & Vigna), seeded through SplitMix64. Distributions are
// written here rather than taken from <random> because the standard leaves their algorithms
// to the library, and a score must not change with the standard library.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "core/branchless.hpp"
#include "core/math.hpp"

namespace sd {

class Rng {
 public:
  explicit Rng(std::uint64_t seed = 0) { reseed(seed); }

  void reseed(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& s : state_) s = splitmix64(x);
    coarse_left_ = 0;
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }

  /// Uniform in [a, b) with 21 random bits: three per 64-bit draw. For sensor noise, where
  /// a resolution of 5e-7 of the noise interval is far below anything a controller sees.
  double coarse_uniform(double a, double b) {
    double v;
    coarse_uniforms(a, b, &v, 1);
    return v;
  }
  /// `n` draws of coarse_uniform(a, b) into `out`, with the generator's state kept in
  /// registers for the whole batch.
  void coarse_uniforms(double a, double b, double* out, int n) {
    std::uint64_t bits = coarse_bits_;
    int left = coarse_left_;
    const double scale = (b - a) * 0x1.0p-21;
    for (int k = 0; k < n; ++k) {
      if (left == 0) {
        bits = next();
        left = 3;
      }
      out[k] = a + scale * static_cast<double>(bits & 0x1fffff);
      bits >>= 21;
      --left;
    }
    coarse_bits_ = bits;
    coarse_left_ = left;
  }
  /// Integer uniform in [a, b) as ARGoS' Uniform(CRange<UInt32>(a, b)); returns a when b <= a.
  std::uint32_t uniform_int(std::uint32_t a, std::uint32_t b) {
    if (b <= a) return a;
    return a + static_cast<std::uint32_t>(uniform() * static_cast<double>(b - a));
  }
  /// Integer uniform in [0, n) for shuffling; n > 0.
  std::uint32_t below(std::uint32_t n) {
    return static_cast<std::uint32_t>(((next() >> 32) * n) >> 32);  // Lemire, bias < 2^-32
  }
  bool bernoulli(double p) { return uniform() < p; }

  /// Standard normal by the ziggurat method (Marsaglia and Tsang 2000, 256 layers): one 64-bit
  /// draw gives the layer (8 bits), the sign (1 bit) and the position (53 bits), and 98.5 % of
  /// draws are accepted at once, without a logarithm. The layers are computed once, with
  /// math::exp and math::log, so they are the same on every machine.
  double normal() {
    const Ziggurat& z = ziggurat();
    for (;;) {
      const std::uint64_t bits = next();
      const std::size_t i = bits & 0xff;
      const bool negative = (bits & 0x100) != 0;
      const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.x[i];
      if (x < z.x[i + 1]) return negate_if(negative, x);  // inside the layer's rectangle under the curve
      if (i == 0) {  // the base layer's tail beyond r (Marsaglia 1964)
        double a, b;
        do {
          a = -math::log(1.0 - uniform()) / Ziggurat::kR;
          b = -math::log(1.0 - uniform());
        } while (b + b < a * a);
        return negate_if(negative, Ziggurat::kR + a);
      }
      // The wedge between the rectangle and the curve: accept under the density.
      if (z.f[i] + uniform() * (z.f[i + 1] - z.f[i]) < math::exp(-0.5 * x * x)) return negate_if(negative, x);
    }
  }

  /// The full generator state, for checkpointing a design process.
  struct State {
    std::uint64_t s[4];
    std::uint64_t coarse_bits;
    int coarse_left;
  };
  State state() const {
    return {{state_[0], state_[1], state_[2], state_[3]}, coarse_bits_, coarse_left_};
  }
  void set_state(const State& st) {
    for (int i = 0; i < 4; ++i) state_[i] = st.s[i];
    coarse_bits_ = st.coarse_bits;
    coarse_left_ = st.coarse_left;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  /// Layer i (0..255) spans [0, x[i]] between heights f[i] = e^(-x[i]^2/2) and f[i + 1]; all
  /// have the same area v. Layer 0 is the rectangle under f(r) plus the tail beyond r = x[1],
  /// so x[0] = v / f(r); x[256] = 0 is the peak.
  struct Ziggurat {
    static constexpr double kR = 3.654152885361009;     // r and v for 256 layers (mpmath)
    static constexpr double kV = 0.004928673233974655;
    double x[257], f[257];
    Ziggurat() {
      const double fr = math::exp(-0.5 * kR * kR);
      x[0] = kV / fr;
      f[0] = 0.0;
      x[1] = kR;
      f[1] = fr;
      for (int i = 1; i < 255; ++i) {
        x[i + 1] = std::sqrt(-2.0 * math::log(kV / x[i] + f[i]));
        f[i + 1] = math::exp(-0.5 * x[i + 1] * x[i + 1]);
      }
      x[256] = 0.0;
      f[256] = 1.0;
    }
  };
  static const Ziggurat& ziggurat() {
    static const Ziggurat table;
    return table;
  }

  std::uint64_t state_[4];
  std::uint64_t coarse_bits_ = 0;
  int coarse_left_ = 0;
};

}  // namespace sd
