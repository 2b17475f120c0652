#include "core/json_integer.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>

namespace {

using nlohmann::json;

TEST(JsonInteger, ReadsIntegersWithinTheRange) {
  EXPECT_EQ(sd::json_integer<int>(json::parse("42")), 42);
  EXPECT_EQ(sd::json_integer<int>(json::parse("-7")), -7);
  EXPECT_EQ(sd::json_integer<int>(json::parse("2147483647")), 2147483647);
  EXPECT_EQ(sd::json_integer<std::uint64_t>(json::parse("18446744073709551615")), UINT64_MAX);
  EXPECT_EQ(sd::json_integer<std::int64_t>(json::parse("-9223372036854775808")), INT64_MIN);
}

// The fuzzer's finding: 2.09e118 in EvoStick's settings went through get<int>(), undefined
// behaviour; a number beyond the type's range must be refused, not wrapped or converted.
TEST(JsonInteger, RefusesNumbersTheTypeCannotHold) {
  EXPECT_FALSE(sd::json_integer<int>(json::parse("2.09e118")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("2147483648")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("-2147483649")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("1099511627776")));  // 2^40 would wrap to 0
  EXPECT_FALSE(sd::json_integer<std::uint64_t>(json::parse("-1")));
  EXPECT_FALSE(sd::json_integer<std::size_t>(json::parse("-3")));
}

TEST(JsonInteger, RefusesWhatIsNoInteger) {
  EXPECT_FALSE(sd::json_integer<int>(json::parse("2.5")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("2.0")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("\"2\"")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("true")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("null")));
  EXPECT_FALSE(sd::json_integer<int>(json::parse("[1]")));
}

}  // namespace
