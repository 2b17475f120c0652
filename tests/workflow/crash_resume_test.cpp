// Designs killed inside a write of their design database (SWARMDESIGN_POWER_CUT, storage/
// power_cut.hpp: a torn file write, then SIGKILL, as a power cut would leave it) resume and end
// exactly as an uninterrupted design. Found by bench/crash_loop.py: a design killed while it
// created its design.db left a file without tables that every resume refused.
#include <gtest/gtest.h>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

class crash_resume : public WorkflowTest {
 protected:
  void SetUp() override {
    WorkflowTest::SetUp();
    mission_ = write_short_mission(scratch()).string();
  }
  /// The uninterrupted design's report (the smallest space: BT with Maple at its least budget).
  json reference() {
    return json::parse(run_ok({"design", "--mission", mission_, "--budget", "728", "--bt", "--maple", "--seed", "7",
                               "--threads", "1", "--out", (scratch() / "reference").string(), "--json"}));
  }
  /// Runs swarmdesign with the power cut at `cut` (N:K); expects it to die by its SIGKILL.
  void killed_at(const std::string& cut, const std::vector<std::string>& args) {
    Environment environment = this->environment();
    environment.set["SWARMDESIGN_POWER_CUT"] = cut;
    const Outcome outcome = run_swarmdesign(args, "", environment);
    ASSERT_EQ(outcome.exit_code, -1) << "not killed at " << cut << ": " << outcome.out << outcome.err;
  }
  std::string mission_;
};

TEST_F(crash_resume, RunDesignKilledWhileCreatingItsDatabaseOrWritingACheckpointResumesExactly) {
  const json expected = reference();
  user_with_active_project("alice", "swarm");
  run_ok({"set-mission", mission_});
  run_ok({"set-budget", "728"});
  const std::vector<std::string> start{"run-design", "--bt", "--maple", "--seed", "7", "--threads", "1"};
  const auto folder = home() / "users" / "alice" / "projects" / "swarm" / "designs" / "1";
  // The first file write of design.db's creation, one in its middle, then the third checkpoint's.
  killed_at("1:1", start);
  killed_at("1:4", start);
  EXPECT_FALSE(std::filesystem::exists(folder / "design.db")) << "a design.db without its tables is left behind";
  killed_at("4:3", start);
  EXPECT_EQ(checkpoint_step(folder), 2);

  const std::string resumed = run_ok(start);
  EXPECT_NE(resumed.find("resuming"), std::string::npos) << resumed;
  EXPECT_EQ(query("SELECT count(*) || ' ' || state FROM designs"), "1 finished");
  EXPECT_EQ(query("SELECT best_config FROM designs"), expected["best"]["configuration"].get<std::string>());
  EXPECT_EQ(experiment_log(folder), experiment_log(scratch() / "reference"));
}

// Found by a check kept apart (bench/crash_loop.py's late re-run): a kill that came after the
// design had finished, then the same command as a resume, designed it again as design 2.
TEST_F(crash_resume, TheSameRunDesignAfterItsDesignFinishedFindsTheResultInsteadOfDesigningAgain) {
  user_with_active_project("alice", "swarm");
  run_ok({"set-mission", mission_});
  run_ok({"set-budget", "728"});
  const std::vector<std::string> start{"run-design", "--bt", "--maple", "--seed", "7", "--threads", "1"};
  run_ok(start);
  const std::string best = query("SELECT best_config FROM designs WHERE id = 1");

  const std::string again = run_ok(start);
  EXPECT_NE(again.find("Design 1 already finished"), std::string::npos) << again;
  EXPECT_NE(again.find(best), std::string::npos) << again;
  EXPECT_EQ(query("SELECT count(*) || ' ' || state FROM designs"), "1 finished");
  EXPECT_FALSE(std::filesystem::exists(home() / "users" / "alice" / "projects" / "swarm" / "designs" / "2"));

  // Another seed, or --new, is a new design; --new with the same seed repeats the first exactly.
  run_ok({"run-design", "--bt", "--maple", "--seed", "7", "--threads", "1", "--new"});
  EXPECT_EQ(query("SELECT count(*) FROM designs WHERE state = 'finished'"), "2");
  EXPECT_EQ(query("SELECT best_config FROM designs WHERE id = 2"), best);
  EXPECT_EQ(experiment_log(home() / "users" / "alice" / "projects" / "swarm" / "designs" / "2"),
            experiment_log(home() / "users" / "alice" / "projects" / "swarm" / "designs" / "1"));
}

TEST_F(crash_resume, TheDesignCommandKilledWhileCreatingItsDatabaseRunsAgainWithTheSameCommand) {
  const json expected = reference();
  const std::vector<std::string> start{"design", "--mission", mission_, "--budget", "728", "--bt", "--maple",
                                       "--seed", "7", "--threads", "1", "--out", (scratch() / "killed").string(), "--json"};
  killed_at("1:2", start);
  const json again = json::parse(run_ok(start));
  EXPECT_EQ(again["best"], expected["best"]);
  EXPECT_EQ(experiment_log(scratch() / "killed"), experiment_log(scratch() / "reference"));
}

}  // namespace
}  // namespace sd::test
