// One FNV-1a serves every stored digest (design fingerprints, mission digests, network
// weights), so it must be the published function: checked against its test vectors.
#include "core/fnv.hpp"

#include <gtest/gtest.h>

namespace sd {
namespace {

std::uint64_t of(std::string_view text) {
  Fnv1a f;
  f.add(text);
  return f.value();
}

TEST(Fnv1a, MatchesThePublishedTestVectors) {
  EXPECT_EQ(of(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(of("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(of("foobar"), 0x85944171f73967e8ull);
}

TEST(Fnv1a, AddsIntegersLeastSignificantByteFirstAndPrintsSixteenHexDigits) {
  Fnv1a bytes, word;
  for (const char c : std::string_view("\x01\x02\x03\x04\x05\x06\x07\x08", 8)) bytes.add(static_cast<unsigned char>(c));
  word.add_u64(0x0807060504030201ull);
  EXPECT_EQ(word.value(), bytes.value());
  Fnv1a empty;
  EXPECT_EQ(empty.hex(), "cbf29ce484222325");
  EXPECT_EQ(Fnv1a(0).hex(), "0000000000000000");
}

}  // namespace
}  // namespace sd
