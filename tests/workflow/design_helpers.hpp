#pragma once
// What the design tests share: a short mission (so that a design of a thousand runs takes
// seconds), reading a running design's checkpoint counter, and killing at the right moment.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "sanitized.hpp"

namespace sd::test {

/// The design tests' runs: 10 simulated seconds in Release; 2 under a sanitizer, which makes
/// each tick about ten times slower. Every tick runs the same code, so what a sanitizer checks
/// is unchanged, and a test that needs a design still running waits longer there than in
/// Release all the same (docs/hardening.md).
inline constexpr int kShortMissionSeconds = kSanitized ? 2 : 10;

/// missions/aac.json with "duration" set to `seconds`, written as folder/aac-short.json.
std::filesystem::path write_short_mission(const std::filesystem::path& folder, int seconds = kShortMissionSeconds);

/// The design's checkpoint counter (0 while it has none), read as `status` would.
std::int64_t checkpoint_step(const std::filesystem::path& design_folder);

/// Polls `condition` every 10 ms until it holds (true) or `timeout` passes (false).
bool wait_until(const std::function<bool()>& condition, std::chrono::milliseconds timeout);

/// The parts of a design's --json report that must not depend on how it was run (threads,
/// interruptions, folder, timing).
nlohmann::json design_outcome(const std::string& json_report);

/// One line per experiment of DIR/design.db: iteration, position, seed, configuration, cost.
std::string experiment_log(const std::filesystem::path& design_folder);

}  // namespace sd::test
