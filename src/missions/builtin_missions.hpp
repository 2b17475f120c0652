#pragma once
// The project's missions/*.json, compiled into the binary so it runs from anywhere.
#include <span>
#include <string_view>

namespace sd {

struct BuiltinMission {
  std::string_view name;  // file name without .json
  std::string_view json;
};

std::span<const BuiltinMission> builtin_missions();

}  // namespace sd
