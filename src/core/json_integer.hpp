#pragma once
// An integer read from a JSON value only after its range is checked: nlohmann's get<int>() on
// 1e300 (stored as a double) is undefined behaviour, and on 2^40 (stored as an integer) it
// silently wraps to another number. Templated on the JSON type so core needs no JSON library.
#include <cstdint>
#include <optional>
#include <utility>

namespace sd {

/// `value` as Int when it holds an integer (not 2.5, not 1e300, not "2") that Int can
/// represent; otherwise nullopt, for the caller to name what is wrong.
template <class Int, class Json>
std::optional<Int> json_integer(const Json& value) {
  if (value.is_number_unsigned()) {
    const auto v = value.template get<std::uint64_t>();
    if (!std::in_range<Int>(v)) return std::nullopt;
    return static_cast<Int>(v);
  }
  if (value.is_number_integer()) {
    const auto v = value.template get<std::int64_t>();
    if (!std::in_range<Int>(v)) return std::nullopt;
    return static_cast<Int>(v);
  }
  return std::nullopt;
}

}  // namespace sd
