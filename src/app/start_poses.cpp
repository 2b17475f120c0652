#include "app/start_poses.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>

#include "app/errors.hpp"
#include "core/bounded_file.hpp"

namespace sd::app {

namespace {

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::optional<double> number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> robot_index(std::string_view name) {
  if (name.rfind("epuck", 0) == 0) name.remove_prefix(5);
  int value = -1;
  const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), value);
  if (error != std::errc() || end != name.data() + name.size() || name.empty()) return std::nullopt;
  return value;
}

}  // namespace

std::vector<StartPose> start_poses_from_trace(const std::string& text, int robots) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) throw InvalidRequest("the start trace is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string_view> header = fields(line);
  auto column = [&header](std::string_view name) {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return c;
    throw InvalidRequest("the start trace has no column '" + std::string(name) + "' (line 1)");
  };
  const std::size_t tick = column("tick"), robot = column("robot"), x = column("x"), y = column("y"), yaw = column("yaw");
  const std::size_t needed = std::max({tick, robot, x, y, yaw}) + 1;

  std::vector<std::optional<StartPose>> poses(static_cast<std::size_t>(robots));
  int found = 0;
  for (int number_of_line = 2; std::getline(in, line); ++number_of_line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string_view> f = fields(line);
    const std::string at = "the start trace's line " + std::to_string(number_of_line);
    if (f.size() < needed) throw InvalidRequest(at + " has " + std::to_string(f.size()) + " fields, not " + std::to_string(needed));
    if (f[tick] != "0") {
      if (!number(f[tick])) throw InvalidRequest(at + ": the tick '" + std::string(f[tick].substr(0, 20)) + "' is no number");
      break;  // tick 0 comes first: the rest of the file is the run
    }
    const std::optional<int> r = robot_index(f[robot]);
    if (!r || *r < 0 || *r >= robots)
      throw InvalidRequest(at + ": '" + std::string(f[robot].substr(0, 20)) + "' is no robot of the mission's " +
                           std::to_string(robots) + " (epuck0 to epuck" + std::to_string(robots - 1) + ")");
    const std::optional<double> px = number(f[x]), py = number(f[y]), pyaw = number(f[yaw]);
    if (!px || !py || !pyaw) throw InvalidRequest(at + ": x, y and yaw must be finite numbers");
    if (std::abs(*px) > 10.0 || std::abs(*py) > 10.0) throw InvalidRequest(at + ": the robot lies beyond 10 m from the origin");
    auto& slot = poses[static_cast<std::size_t>(*r)];
    if (slot) throw InvalidRequest(at + ": robot " + std::string(f[robot]) + " appears twice at tick 0");
    slot = StartPose{{*px, *py}, *pyaw};
    ++found;
  }
  if (found != robots)
    throw InvalidRequest("the start trace has " + std::to_string(found) + " robots at tick 0; the mission has " +
                         std::to_string(robots));
  std::vector<StartPose> out;
  out.reserve(poses.size());
  for (const auto& pose : poses) out.push_back(*pose);
  return out;
}

Mission with_start_from(const Mission& mission, const std::string& path) {
  if (path.empty()) return mission;
  std::string text;
  try {
    // A 20-robot, 1200-tick trace is about 2 MB; 64 MiB leaves room for long runs of large swarms.
    text = read_bounded_file(path, "start trace", std::size_t{64} << 20).text;
  } catch (const FileReadError& e) {
    throw InvalidRequest(e.what());
  }
  Mission started = mission;
  started.start_poses = start_poses_from_trace(text, mission.robots);
  return started;
}

}  // namespace sd::app
