// Start traces as `evaluate --start-from` reads them (ARGoS' tick-0 files, our --trace files).
// Byte 0 (mod 40, plus 1) is the mission's robot count; the rest is the trace's text.
// MissionError is the reader's one rejection; any other exception is a finding, and so is an
// accepted trace whose poses are not one finite pose within 10 m per robot.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "finding.hpp"
#include "missions/start_trace.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const int robots = 1 + data[0] % 40;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const std::vector<sd::StartPose> poses = sd::start_poses_from_trace(text, robots);
    if (poses.size() != static_cast<std::size_t>(robots)) sd::fuzz::finding("accepted a trace with another robot count");
    for (const sd::StartPose& p : poses)
      if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y) || !std::isfinite(p.yaw) ||
          std::abs(p.position.x) > 10.0 || std::abs(p.position.y) > 10.0)
        sd::fuzz::finding("accepted a pose that is not finite or lies beyond 10 m");
  } catch (const sd::MissionError&) {
    // The documented rejection.
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than MissionError: ") + e.what());
  }
  return 0;
}
