#include "workflow/design_helpers.hpp"

#include <charconv>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "storage/sqlite.hpp"
#include "test_paths.hpp"

namespace sd::test {

std::filesystem::path write_short_mission(const std::filesystem::path& folder, int seconds) {
  std::ifstream in(std::filesystem::path(::sd::test::source_dir()) / "missions" / "aac.json");
  std::stringstream text;
  text << in.rdbuf();
  const std::string shortened = std::regex_replace(text.str(), std::regex("\"duration\": *[0-9.]+"),
                                                   "\"duration\": " + std::to_string(seconds));
  const auto path = folder / "aac-short.json";
  std::ofstream(path) << shortened;
  return path;
}

std::int64_t checkpoint_step(const std::filesystem::path& design_folder) {
  const auto file = design_folder / "design.db";
  if (!std::filesystem::exists(file)) return 0;
  try {
    storage::Database db(file, false);
    auto q = db.prepare("SELECT step FROM checkpoint WHERE id = 1");
    return q.step() ? q.integer(0) : 0;
  } catch (const storage::DatabaseError&) {
    return 0;  // created but its tables not committed yet
  }
}

bool wait_until(const std::function<bool()>& condition, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}

nlohmann::json design_outcome(const std::string& json_report) {
  const auto report = nlohmann::json::parse(json_report);
  return {{"best", report.at("best")},
          {"elites", report.at("elites")},
          {"experiments_used", report.at("experiments_used")},
          {"iterations", report.at("iterations")},
          {"finish_reason", report.at("finish_reason")}};
}

std::string experiment_log(const std::filesystem::path& design_folder) {
  storage::Database db(design_folder / "design.db", false);
  auto q = db.prepare("SELECT seq, iteration, position, seed, configuration_id, cost FROM experiments ORDER BY seq");
  std::string out;
  while (q.step()) {
    for (int c = 0; c < 5; ++c) out += q.text(c) + " ";
    char cost[40] = "NULL";
    if (!q.is_null(5)) *std::to_chars(cost, cost + sizeof cost - 1, q.real(5)).ptr = '\0';  // exact, shortest
    out += std::string(cost) + "\n";
  }
  return out;
}

}  // namespace sd::test
