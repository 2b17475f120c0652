#include "missions/start_trace.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

#include "core/bounded_file.hpp"
#include "core/csv_fields.hpp"

namespace sd {

namespace {

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

/// Hands out the text's lines one at a time, without their '\n'.
class Lines {
 public:
  explicit Lines(std::string_view text) : rest_(text) {}
  bool next(std::string_view& line) {
    if (rest_.empty()) return false;
    const std::size_t end = rest_.find('\n');
    line = rest_.substr(0, end);
    rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
    return true;
  }

 private:
  std::string_view rest_;
};

}  // namespace

std::vector<StartPose> start_poses_from_trace(std::string_view text, int robots) {
  Lines lines(text);
  std::string_view line;
  if (!lines.next(line)) throw MissionError("the start trace is empty");
  const std::vector<std::string_view> header = csv_fields(line);
  auto column = [&header](std::string_view name) {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return c;
    throw MissionError("the start trace has no column '" + std::string(name) + "' (line 1)");
  };
  const std::size_t tick = column("tick"), robot = column("robot"), x = column("x"), y = column("y"), yaw = column("yaw");
  const std::size_t needed = std::max({tick, robot, x, y, yaw}) + 1;

  std::vector<std::optional<StartPose>> poses(static_cast<std::size_t>(robots));
  int found = 0;
  for (int number_of_line = 2; lines.next(line); ++number_of_line) {
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string_view> f = csv_fields(line);
    const std::string at = "the start trace's line " + std::to_string(number_of_line);
    if (f.size() < needed) throw MissionError(at + " has " + std::to_string(f.size()) + " fields, not " + std::to_string(needed));
    if (f[tick] != "0") {
      if (!number(f[tick])) throw MissionError(at + ": the tick '" + std::string(f[tick].substr(0, 20)) + "' is no number");
      break;  // tick 0 comes first: the rest of the file is the run
    }
    const std::optional<int> r = robot_index(f[robot]);
    if (!r || *r < 0 || *r >= robots)
      throw MissionError(at + ": '" + std::string(f[robot].substr(0, 20)) + "' is no robot of the mission's " +
                           std::to_string(robots) + " (epuck0 to epuck" + std::to_string(robots - 1) + ")");
    const std::optional<double> px = number(f[x]), py = number(f[y]), pyaw = number(f[yaw]);
    if (!px || !py || !pyaw) throw MissionError(at + ": x, y and yaw must be finite numbers");
    if (std::abs(*px) > 10.0 || std::abs(*py) > 10.0) throw MissionError(at + ": the robot lies beyond 10 m from the origin");
    auto& slot = poses[static_cast<std::size_t>(*r)];
    if (slot) throw MissionError(at + ": robot " + std::string(f[robot]) + " appears twice at tick 0");
    slot = StartPose{{*px, *py}, *pyaw};
    ++found;
  }
  if (found != robots)
    throw MissionError("the start trace has " + std::to_string(found) + " robots at tick 0; the mission has " +
                         std::to_string(robots));
  std::vector<StartPose> out;
  out.reserve(poses.size());
  for (const auto& pose : poses) out.push_back(*pose);
  return out;
}

Mission started_from_trace(const Mission& mission, const std::filesystem::path& path) {
  std::string text;
  try {
    // 64 MiB leaves room for long runs of large swarms.
    text = read_bounded_file(path, "start trace", std::size_t{64} << 20).text;
  } catch (const FileReadError& e) {
    throw MissionError(e.what());
  }
  Mission started = mission;
  started.start_poses = start_poses_from_trace(text, mission.robots);
  return started;
}

}  // namespace sd
