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
#include <cstdint>
#include <numbers>

namespace sd {

class Rng {
 public:
  explicit Rng(std::uint64_t seed = 0) { reseed(seed); }

  void reseed(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& s : state_) s = splitmix64(x);
    has_spare_normal_ = false;
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

  /// Standard normal, Marsaglia's polar method (one spare kept).
  double normal() {
    if (has_spare_normal_) {
      has_spare_normal_ = false;
      return spare_normal_;
    }
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_normal_ = v * f;
    has_spare_normal_ = true;
    return u * f;
  }

  /// The full generator state, for checkpointing a design process.
  struct State {
    std::uint64_t s[4];
    bool has_spare;
    double spare;
    std::uint64_t coarse_bits;
    int coarse_left;
  };
  State state() const {
    return {{state_[0], state_[1], state_[2], state_[3]}, has_spare_normal_, spare_normal_, coarse_bits_, coarse_left_};
  }
  void set_state(const State& st) {
    for (int i = 0; i < 4; ++i) state_[i] = st.s[i];
    has_spare_normal_ = st.has_spare;
    spare_normal_ = st.spare;
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

  std::uint64_t state_[4];
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
  std::uint64_t coarse_bits_ = 0;
  int coarse_left_ = 0;
};

}  // namespace sd
