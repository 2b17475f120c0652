#pragma once
// An integer read from a JSON value only after its range is checked: nlohmann's get<int>() on
// 1e300 (stored as a double) is undefined behaviour, and on 2^40 (stored as an integer) it
// silently wraps to another number. Templated on the JSON type so core needs no JSON library.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
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

/// `value` as Int, or std::runtime_error naming `what` when it is no integer Int can hold. For
/// the files SwarmDesign writes itself (a design's state, a cluster job's progress): a damaged
/// or tampered one is refused in one line instead of converted with undefined behaviour.
template <class Int, class Json>
Int checked_json_integer(const Json& value, const std::string& what) {
  if (const std::optional<Int> v = json_integer<Int>(value)) return *v;
  throw std::runtime_error(what + " is not an integer in range");
}

}  // namespace sd
