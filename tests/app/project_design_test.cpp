// Designs of a project through the application layer, as a web server will run them: the job
// leases the design, releases it when cancelled, status reads it as interrupted, the next
// start resumes it; and two designs running at once in one process share one thread pool and
// still end bit for bit as they do alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <thread>

#include "app/accounts.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "app/design_backends.hpp"
#include "app/project_design.hpp"
#include "app/test_design.hpp"
#include "app/projects.hpp"
#include "core/executor.hpp"
#include "storage/lease.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

class CancelAt final : public app::DesignObserver {
 public:
  explicit CancelAt(std::int64_t step) : step_(step) {}
  void checkpoint(std::int64_t step) override {
    if (step == step_) token.cancel();
  }
  app::CancelToken token;

 private:
  std::int64_t step_;
};

class ProjectDesign : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("sd-project-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
    home_.emplace(root_ / "home");
    mission_ = write_short_mission(root_).string();
    user_ = app::sign_up(*home_, "alice", "correct horse battery");
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  void project(const std::string& name, const std::string& budget = "1100") {
    app::create_project(*home_, user_, name, std::nullopt);
    app::select_project(*home_, user_, name);
    app::set_mission(*home_, user_, mission_);
    app::set_budget(*home_, user_, budget);
  }
  app::ProjectDesignRequest request(std::uint64_t seed) const {
    app::ProjectDesignRequest r;
    r.space.fsm = true;
    r.space.flavours = {Flavour::Chocolate};
    r.seed = seed;
    r.owner = storage::owner_text(storage::server_thread("test"));
    return r;
  }

  std::filesystem::path root_;
  std::optional<app::Home> home_;
  std::string mission_;
  storage::User user_;
};

TEST_F(ProjectDesign, ACancelledDesignIsInterruptedAndTheNextStartResumesIt) {
  project("swarm");
  app::ProjectDesign first = app::start_project_design(*home_, user_, request(7));
  EXPECT_FALSE(first.resumed);
  EXPECT_EQ(first.design.state, storage::DesignState::running);
  CancelAt stop(9);
  const app::DesignOutcome stopped = app::run_project_design(first, {.threads = 2, .observer = &stop, .cancel = &stop.token});
  EXPECT_TRUE(stopped.cancelled);

  const app::DesignStatus interrupted = app::design_status(*home_, user_, app::StatusDetail::progress);
  ASSERT_TRUE(interrupted.design);
  EXPECT_EQ(interrupted.design->state, storage::DesignState::interrupted);
  EXPECT_TRUE(interrupted.progress.started);
  EXPECT_GT(interrupted.progress.race_alive, 0);
  EXPECT_LE(interrupted.progress.race_alive, interrupted.progress.race_configurations);
  const nlohmann::json brief = app::status_document(interrupted, app::StatusDetail::progress);
  EXPECT_EQ(brief["design"]["state"], "interrupted");
  EXPECT_FALSE(brief.contains("race_log"));
  EXPECT_FALSE(brief.contains("convergence"));

  app::ProjectDesign again = app::start_project_design(*home_, user_, request(999));  // the seed given is ignored
  EXPECT_TRUE(again.resumed);
  EXPECT_EQ(again.design.id, first.design.id);
  const app::DesignOutcome done = app::run_project_design(again, {.threads = 1});
  ASSERT_TRUE(done.report);

  const app::DesignStatus finished = app::design_status(*home_, user_, app::StatusDetail::complete);
  EXPECT_EQ(finished.design->state, storage::DesignState::finished);
  EXPECT_EQ(*finished.design->best_config, done.report->elites.front().configuration);
  EXPECT_EQ(finished.progress.best->command_line, done.report->elites.front().configuration);
  ASSERT_FALSE(finished.race_log.empty());
  // The count of the alive is the last race's, as its log ends.
  const auto& last = finished.race_log.back().members;
  EXPECT_EQ(finished.progress.race_alive,
            std::count_if(last.begin(), last.end(), [](const storage::RaceMember& m) { return !m.eliminated_after; }));
  // A page's poll: the convergence without the race log.
  const app::DesignStatus polled = app::design_status(*home_, user_, app::StatusDetail::convergence);
  EXPECT_TRUE(polled.race_log.empty());
  EXPECT_EQ(polled.convergence.size(), finished.convergence.size());
  const nlohmann::json poll = app::status_document(polled, app::StatusDetail::convergence);
  EXPECT_FALSE(poll.contains("race_log"));
  EXPECT_EQ(poll["progress"]["race_alive"], finished.progress.race_alive);

  // The same design uninterrupted, in a fresh project: the same result.
  project("again");
  app::ProjectDesign whole = app::start_project_design(*home_, user_, request(7));
  const app::DesignOutcome reference = app::run_project_design(whole, {.threads = 2});
  EXPECT_EQ(design_outcome(app::design_report_document(*reference.report).dump()),
            design_outcome(app::design_report_document(*done.report).dump()));

  // test-design's target is that design's best on the project's mission.
  const app::TestTarget target = app::test_target(*home_, user_, std::nullopt);
  EXPECT_EQ(target.design_id, whole.design.id);
  EXPECT_EQ(target.configuration, reference.report->elites.front().configuration);
  // A design's best runs on the design's own mission (app::design_best), even once the project
  // has been set to another one: /test and the assessment never score it on different missions.
  app::set_mission(*home_, user_, "foraging");
  const app::TestTarget after = app::test_target(*home_, user_, std::nullopt);
  EXPECT_EQ(after.design_id, whole.design.id);
  EXPECT_EQ(after.mission.name, target.mission.name);
  EXPECT_EQ(after.mission.ticks, target.mission.ticks);
  EXPECT_NE(after.mission.name, "foraging");
}

TEST_F(ProjectDesign, TwoDesignsAtOnceShareThePoolAndEndAsTheyDoAlone) {
  project("a");
  app::ProjectDesign a = app::start_project_design(*home_, user_, request(3));
  project("b");
  app::ProjectDesign b = app::start_project_design(*home_, user_, request(4));
  // Another running design in the same project is refused, not started twice.
  EXPECT_THROW(app::start_project_design(*home_, user_, request(5)), app::Conflict);

  std::optional<app::DesignOutcome> outcome_a, outcome_b;
  std::thread other([&] { outcome_a = app::run_project_design(a, {.threads = 0}); });
  outcome_b = app::run_project_design(b, {.threads = 0});
  other.join();
  ASSERT_TRUE(outcome_a && outcome_a->report && outcome_b->report);
  EXPECT_LE(Executor::shared().size(), static_cast<std::size_t>(resolve_threads(0u)))
      << "two all-core designs must share the cores, not double the threads";

  project("a-alone");
  app::ProjectDesign alone = app::start_project_design(*home_, user_, request(3));
  const app::DesignOutcome reference = app::run_project_design(alone, {.threads = 1});
  EXPECT_EQ(design_outcome(app::design_report_document(*reference.report).dump()),
            design_outcome(app::design_report_document(*outcome_a->report).dump()));
}

TEST_F(ProjectDesign, MisuseAndRefusalsAreTheirOwnKinds) {
  EXPECT_THROW(app::set_budget(*home_, user_, "12"), app::NotFound);  // no active project yet
  project("p");
  EXPECT_THROW(app::set_budget(*home_, user_, "ten"), app::InvalidRequest);
  EXPECT_THROW(app::set_mission(*home_, user_, "no-such-mission"), app::InvalidRequest);
  EXPECT_THROW(app::create_project(*home_, user_, "p", std::nullopt), app::Conflict);
  EXPECT_THROW(app::create_project(*home_, user_, "../escape", std::nullopt), app::InvalidRequest);
  EXPECT_THROW(app::test_target(*home_, user_, std::nullopt), app::NotFound);  // nothing designed yet
  // A mission file given by a relative name is kept by absolute path.
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(root_);
  app::set_mission(*home_, user_, "aac-short.json");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(*app::active_project(*home_, user_).mission, (root_ / "aac-short.json").string());
}

}  // namespace
}  // namespace sd::test
