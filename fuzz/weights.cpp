// EvoStick's documents as Arlequin reads them. The first byte picks what the rest is:
//   0: a module's weight document (arlequin::weights_from_json; std::runtime_error rejects);
//   1: EvoStick settings (evostick::settings_from_json; nlohmann::json::exception rejects the
//      text, std::invalid_argument a field);
//   2: a module-set folder's module-set.json beside six valid weight documents
//      (arlequin::load_module_set; std::runtime_error rejects).
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "evostick/weight_document.hpp"
#include "finding.hpp"
#include "modules/arlequin_module_set.hpp"

namespace {

// A module-set folder of this process: the shipped weight documents, and module-set.json
// rewritten for each input.
const std::filesystem::path& set_folder() {
  static const std::filesystem::path folder = [] {
    const auto dir = std::filesystem::temp_directory_path() / ("sd-fuzz-weights-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (const auto& entry : std::filesystem::directory_iterator(SWARMDESIGN_SOURCE_DIR "/data/arlequin"))
      if (entry.path().extension() == ".json")
        std::filesystem::copy_file(entry.path(), dir / entry.path().filename(),
                                   std::filesystem::copy_options::overwrite_existing);
    return dir;
  }();
  return folder;
}

void weight_document(const std::string& text) {
  try {
    (void)sd::arlequin::weights_from_json(text, "fuzz.json");
  } catch (const std::runtime_error&) {
  }
}

void settings(const std::string& text) {
  try {
    (void)sd::evostick::settings_from_json(nlohmann::json::parse(text));
  } catch (const nlohmann::json::exception&) {
  } catch (const std::invalid_argument&) {
  }
}

void module_set(const std::string& text) {
  std::ofstream(set_folder() / "module-set.json", std::ios::binary | std::ios::trunc) << text;
  try {
    (void)sd::arlequin::load_module_set(set_folder().string());
  } catch (const std::runtime_error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: weight_document(text); break;
      case 1: settings(text); break;
      default: module_set(text); break;
    }
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("undocumented exception: ") + e.what());
  }
  return 0;
}
