// Mission files as a user writes them (missions/*.json's format). MissionError is the one
// rejection. A mission that parses is also drawn (what /api/missions/svg serves) and read
// back from its own document, which must give the same digest. Folders an
// "arlequin_modules" field names are refused unread, so an input never reads the disk.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>

#include "finding.hpp"
#include "missions/mission.hpp"
#include "missions/svg.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const sd::PathRule nowhere = [](const std::filesystem::path&) { return false; };
  sd::Mission mission;
  try {
    mission = sd::parse_mission(text, "fuzz.json", nowhere);
  } catch (const sd::MissionError&) {
    return 0;
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than MissionError: ") + e.what());
  }
  try {
    (void)sd::mission_svg(mission);
    const sd::Mission again = sd::parse_mission(mission.document, "fuzz.json", nowhere);
    if (again.digest != mission.digest) sd::fuzz::finding("its own document reads back with another digest");
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("a mission that parsed fails to draw or re-read: ") + e.what());
  }
  return 0;
}
