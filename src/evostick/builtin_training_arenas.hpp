#pragma once
// The Arlequin training arenas, data/arlequin/training/*.json, compiled into the binary (see
// src/modules/embed_json_files.cmake) so `swarmdesign evostick --module` runs from anywhere.
#include <span>
#include <string_view>

namespace sd::evostick {

struct BuiltinTrainingArena {
  std::string_view name;  // file name without .json
  std::string_view json;
};

std::span<const BuiltinTrainingArena> builtin_training_arenas();

}  // namespace sd::evostick
