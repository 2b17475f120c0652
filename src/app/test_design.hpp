#pragma once
// Scoring a design's best (or given control software) on fresh seeds, and two designs against
// each other: the services behind test-design and compare-designs (CLI), /test and /compare (web)
// and Python's test_design/compare_designs. Each front end only parses its request and prints or
// sends the document these return, so the three give the same document for the same request.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "app/home.hpp"
#include "app/user_files.hpp"
#include "control/control_software.hpp"
#include "missions/mission.hpp"
#include "storage/projects.hpp"

namespace sd::app {

/// What test-design scores: the given control software on the project's mission, or a design's
/// best on its own mission (design_best.hpp: design `design`, else the last with a best).
struct TestTarget {
  storage::Project project;
  Mission mission;
  ControlSoftware software;
  std::optional<std::int64_t> design_id;  // when it is a design's best
  std::string configuration;              // its configuration string
};
TestTarget test_target(Home& home, const storage::User& user, const std::optional<ControlSoftware>& given);
/// The same for one of the user's projects by name (the web page): the given software, or the
/// best of design `design` (NotFound unless it is the project's and has one), or of its last
/// finished design; missions read under `scope`.
TestTarget test_target(Home& home, const storage::User& user, const std::optional<std::string>& project,
                       const std::optional<ControlSoftware>& given, std::optional<std::int64_t> design,
                       const FileScope& scope);

/// What one request may simulate. A web page waits for its answer: at most 100 seeds and 1e8
/// robot ticks in all (page()); the CLI and Python ask for what they will wait for (none()).
struct TestLimits {
  std::size_t max_seeds = 0;     // 0: no limit
  double max_robot_ticks = 0.0;  // 0: no limit
  static TestLimits page() { return {100, 100'000'000.0}; }
  static TestLimits none() { return {}; }
};

struct TestDesignRequest {
  std::optional<std::string> project;       // nullopt: the active one
  std::optional<std::int64_t> design;       // nullopt: the last design with a best
  std::optional<ControlSoftware> software;  // given: scored on the project's mission instead
  std::string seeds = "1-10";
  int threads = 0;
  std::function<void(std::size_t, std::size_t)> progress{};  // runs done, runs in all
};
/// {"mission", "control_software", "seeds", "scores", "mean", "median", ..., "design", "sd"}:
/// score_seeds' document with the design scored (null for given software) and the sample
/// standard deviation (null for one seed).
nlohmann::json test_design(Home& home, const storage::User& user, const TestDesignRequest& request,
                           const FileScope& scope = FileScope::local(), const TestLimits& limits = TestLimits::none());

struct CompareDesignsRequest {
  std::optional<std::string> project;  // nullopt: the active one
  std::int64_t a = 0, b = 0;           // the two designs
  std::string seeds = "1-20";
  int threads = 0;
  std::function<void(std::size_t, std::size_t)> progress{};
};
/// Both designs' bests, each on its own mission, on the same seeds, with the Wilcoxon
/// signed-rank test paired by seed: {"seeds", "designs": [test_design's document ×2], "wilcoxon"}.
nlohmann::json compare_designs(Home& home, const storage::User& user, const CompareDesignsRequest& request,
                               const FileScope& scope = FileScope::local(), const TestLimits& limits = TestLimits::none());

}  // namespace sd::app
