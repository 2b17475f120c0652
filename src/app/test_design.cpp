#include "app/test_design.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

#include "app/design_best.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/evaluation_job.hpp"
#include "app/inputs.hpp"
#include "app/projects.hpp"
#include "control/config_string.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/signed_rank.hpp"

namespace sd::app {

namespace {

/// Fills target.software and .mission for target.project: the given software on the project's
/// mission, or a design's best on its own mission (design_best: design `design`, or the last
/// with a best).
void complete_target(TestTarget& target, Home& home, const storage::User& user, const std::optional<ControlSoftware>& given,
                     std::optional<std::int64_t> design, const FileScope& scope) {
  const storage::Project& project = target.project;
  if (!given) {
    try {
      DesignBest best = design_best(home, user, project.name, design, scope);
      target.design_id = best.design.id;
      target.software = std::move(best.software);
      target.configuration = std::move(best.configuration);
      target.mission = std::move(best.mission);
      return;
    } catch (const NotFound& e) {
      if (design) throw;
      throw NotFound(std::string(e.what()) + ": give the control software (--fsm-config ...) to test");
    }
  }
  if (!project.mission)
    throw NotFound("project " + project.name + " has no mission; choose one with: swarmdesign set-mission");
  target.software = *given;
  target.configuration = to_config_string(*given);
  try {
    target.mission = load_requested_mission(*project.mission, scope);
  } catch (const InvalidRequest& e) {
    throw NotFound("the mission of project " + project.name + " cannot be loaded: " + e.what());
  }
}

}  // namespace

TestTarget test_target(Home& home, const storage::User& user, const std::optional<ControlSoftware>& given) {
  TestTarget target;
  target.project = storage::Projects(home.workspace(), user).require_active();
  complete_target(target, home, user, given, std::nullopt, FileScope::local());
  return target;
}

TestTarget test_target(Home& home, const storage::User& user, const std::optional<std::string>& project,
                       const std::optional<ControlSoftware>& given, std::optional<std::int64_t> design,
                       const FileScope& scope) {
  TestTarget target;
  target.project = project_or_active(home, user, project);
  complete_target(target, home, user, given, design, scope);
  return target;
}

namespace {

std::vector<std::uint64_t> requested_seeds(const std::string& text, const TestLimits& limits) {
  std::vector<std::uint64_t> seeds = parse_seed_range(text);
  if (limits.max_seeds && seeds.size() > limits.max_seeds)
    throw InvalidRequest("seeds " + text + ": at most " + std::to_string(limits.max_seeds) + " seeds from the page");
  return seeds;
}

void require_within(const TestLimits& limits, const Mission& mission, std::size_t runs) {
  if (limits.max_robot_ticks > 0 &&
      static_cast<double>(mission.robots) * mission.ticks * static_cast<double>(runs) > limits.max_robot_ticks)
    throw InvalidRequest("the mission is too long to test on " + std::to_string(runs) +
                         " runs from the page: use swarmdesign test-design");
}

nlohmann::json scored(const TestTarget& target, const std::vector<std::uint64_t>& seeds, const std::vector<double>& scores) {
  nlohmann::json doc = scores_document(target.mission, target.software, seeds, scores);
  doc["design"] = target.design_id ? nlohmann::json(*target.design_id) : nlohmann::json();
  doc["sd"] = scores.size() > 1 ? nlohmann::json(statistics::sample_standard_deviation(scores)) : nlohmann::json();
  return doc;
}


}  // namespace

nlohmann::json test_design(Home& home, const storage::User& user, const TestDesignRequest& request, const FileScope& scope,
                           const TestLimits& limits) {
  const std::vector<std::uint64_t> seeds = requested_seeds(request.seeds, limits);
  const TestTarget target = test_target(home, user, request.project, request.software, request.design, scope);
  require_within(limits, target.mission, seeds.size());
  ScoreOptions options;
  options.threads = request.threads;
  options.progress = request.progress;
  return scored(target, seeds, score_seeds(target.mission, target.software, seeds, options));
}

nlohmann::json compare_designs(Home& home, const storage::User& user, const CompareDesignsRequest& request,
                               const FileScope& scope, const TestLimits& limits) {
  const std::vector<std::uint64_t> seeds = requested_seeds(request.seeds, limits);
  const std::vector<TestTarget> targets = {test_target(home, user, request.project, std::nullopt, request.a, scope),
                                           test_target(home, user, request.project, std::nullopt, request.b, scope)};
  for (const TestTarget& t : targets) require_within(limits, t.mission, 2 * seeds.size());
  nlohmann::json sides = nlohmann::json::array();
  std::vector<std::vector<double>> scores;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    ScoreOptions options;
    options.threads = request.threads;
    if (request.progress)
      options.progress = [&, i](std::size_t done, std::size_t all) { request.progress(i * all + done, 2 * all); };
    scores.push_back(score_seeds(targets[i].mission, targets[i].software, seeds, options));
    sides.push_back(scored(targets[i], seeds, scores.back()));
  }
  nlohmann::json test = {{"test", "Wilcoxon signed-rank, paired by seed"}, {"p_value", 1.0}, {"estimate", 0.0}};
  try {
    const statistics::SignedRankTest t = statistics::wilcoxon_signed_rank(scores[0], scores[1]);
    test["p_value"] = t.p_value;
    test["estimate"] = t.estimate;
    test["statistic"] = t.statistic;
  } catch (const std::invalid_argument&) {
    test["note"] = "every seed scores the same: nothing to tell them apart";
  }
  return {{"seeds", request.seeds}, {"designs", sides}, {"wilcoxon", test}};
}

}  // namespace sd::app
