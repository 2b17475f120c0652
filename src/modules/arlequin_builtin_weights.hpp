#pragma once
// Arlequin data compiled into the binary so that modules 50-55 run from anywhere: the shipped
// weights, data/arlequin/*.json, and Demiurge's set, data/arlequin-demiurge/ (six weight
// documents, module-set.json, grey-samples.csv), generated at build time by
// cmake/embed_json_files.cmake and cmake/embed_text_file.cmake.
#include <span>
#include <string_view>

namespace sd::arlequin {

struct BuiltinWeightFile {
  std::string_view name;  // file name without .json: exploration, stop, ...
  std::string_view json;
};

std::span<const BuiltinWeightFile> builtin_weight_files();
std::span<const BuiltinWeightFile> demiurge_weight_files();
/// data/arlequin-demiurge/grey-samples.csv, verbatim.
std::string_view demiurge_grey_samples_csv();

}  // namespace sd::arlequin
