#pragma once
// The shipped Arlequin weights, data/arlequin/*.json, compiled into the binary (see
// embed_json_files.cmake) so that modules 50-55 run from anywhere.
#include <span>
#include <string_view>

namespace sd::arlequin {

struct BuiltinWeightFile {
  std::string_view name;  // file name without .json: exploration, stop, ...
  std::string_view json;
};

std::span<const BuiltinWeightFile> builtin_weight_files();

}  // namespace sd::arlequin
