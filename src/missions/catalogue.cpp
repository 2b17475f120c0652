#include "missions/catalogue.hpp"

#include <algorithm>
#include <map>

#include "core/home.hpp"
#include "missions/builtin_missions.hpp"

namespace sd {

namespace {

MissionSummary summarize(const Mission& m) {
  return {m.name, m.origin, std::string(direction_name(m.objective.direction)), m.title, m.source, m.robots, m.duration_s};
}

std::filesystem::path user_missions_dir() { return swarmdesign_home() / "missions"; }

}  // namespace

bool is_mission_file(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 5 && s.ends_with(".json"));
}

std::string mission_reference(const std::string& s) {
  return is_mission_file(s) ? std::filesystem::absolute(s).lexically_normal().string() : s;
}

std::vector<MissionSummary> list_missions() {
  std::map<std::string, MissionSummary> by_name;
  for (const BuiltinMission& b : builtin_missions()) {
    MissionSummary s = summarize(parse_mission(std::string(b.json), "built-in"));
    by_name.emplace(s.name, s);
  }
  std::error_code ec;
  const auto dir = user_missions_dir();
  if (std::filesystem::is_directory(dir, ec)) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      MissionSummary s = summarize(load_mission_file(file));
      by_name.insert_or_assign(s.name, s);  // a user's mission of the same name wins
    }
  }
  std::vector<MissionSummary> result;
  result.reserve(result.size() + by_name.size());
  for (auto& [name, s] : by_name) result.push_back(std::move(s));
  return result;
}

Mission load_mission(const std::string& name_or_path) {
  if (is_mission_file(name_or_path)) return load_mission_file(name_or_path);
  const auto user_file = user_missions_dir() / (name_or_path + ".json");
  std::error_code ec;
  if (std::filesystem::is_regular_file(user_file, ec)) return load_mission_file(user_file);
  for (const BuiltinMission& b : builtin_missions())
    if (b.name == name_or_path) return parse_mission(std::string(b.json), "built-in");
  throw MissionError("unknown mission '" + name_or_path + "' (see `swarmdesign missions`, or give a path to a mission file)");
}

bool mission_exists(const std::string& name_or_path) {
  try {
    load_mission(name_or_path);
    return true;
  } catch (const MissionError&) {
    return false;
  }
}

}  // namespace sd
