#pragma once
// 64-bit FNV-1a: a digest that is the same on every build and platform, for telling
// documents and settings apart (a design's parameter space, a mission, a network's
// weights) — not for security (storage/ uses libsodium for that).
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace sd {

class Fnv1a {
 public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  Fnv1a() = default;
  /// Starts from another basis (only to reproduce digests already stored with one).
  explicit Fnv1a(std::uint64_t basis) : h_(basis) {}

  void add(unsigned char byte) { h_ = (h_ ^ byte) * 0x100000001b3ull; }
  void add(std::string_view bytes) {
    for (const unsigned char c : bytes) add(c);
  }
  /// The 8 bytes of `bits`, least significant first.
  void add_u64(std::uint64_t bits) {
    for (int byte = 0; byte < 8; ++byte) add(static_cast<unsigned char>(bits >> (8 * byte)));
  }
  std::uint64_t value() const { return h_; }
  /// 16 lowercase hex digits.
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h_));
    return text;
  }

 private:
  std::uint64_t h_ = kOffsetBasis;
};

}  // namespace sd
