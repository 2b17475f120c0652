#pragma once
// The JSON documents EvoStick prints: a trained module (the format of the shipped
// data/arlequin/<name>.json, read back by arlequin::weights_from_json) and a baseline design
// on a mission. Both hold only what the seed and settings determine (no times, no thread
// counts), so the same command writes the same bytes.
#include <nlohmann/json.hpp>

#include <string>

#include "evostick/evolution.hpp"
#include "evostick/module_training.hpp"

namespace sd::evostick {

/// The command line that reproduces a module's training: the defaults are left out.
std::string module_command(const ModuleTraining& module, const Settings& settings);

nlohmann::json settings_json(const Settings& settings);
/// The settings back from settings_json's document; std::invalid_argument naming a field that is
/// missing, not a number, or not an integer the setting can hold.
Settings settings_from_json(const nlohmann::json& document);
nlohmann::json history_json(const std::vector<GenerationRecord>& history);
/// {"left": [25 weights], "right": [25 weights]}
nlohmann::json weights_json(const arlequin::Weights& weights);

nlohmann::json module_document(const ModuleTraining& module, const Settings& settings, const Result& result);

/// Text the command writes: the document, indented, with a final newline.
std::string document_text(const nlohmann::json& document);

/// "0x" and 16 hexadecimal digits.
std::string digest_text(std::uint64_t digest);

}  // namespace sd::evostick
