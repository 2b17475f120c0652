// `swarmdesign design` end to end: the real binary on a 10-second AAC, killed with SIGKILL and
// resumed, run on 1 and 2 threads, and given folders it must refuse.
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "evaluation/results_version.hpp"
#include "storage/sqlite.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using namespace std::chrono_literals;

class design_command : public WorkflowTest {
 protected:
  void SetUp() override {
    WorkflowTest::SetUp();
    mission_ = write_short_mission(scratch()).string();
  }
  std::vector<std::string> design_args(const std::string& out, int budget, int seed, int threads) const {
    return {"design", "--mission", mission_, "--budget", std::to_string(budget), "--seed", std::to_string(seed),
            "--threads", std::to_string(threads), "--out", (scratch() / out).string(), "--json", "--fsm", "--chocolate"};
  }
  /// Runs a design that is SIGKILLed right after it saves its `steps`-th new checkpoint: the
  /// kill lands at that step exactly, however fast the machine.
  void kill_after(const std::vector<std::string>& args, const std::filesystem::path& folder, std::int64_t steps) {
    const std::int64_t before = checkpoint_step(folder);
    kill_at_checkpoint(before + steps);
    const Outcome killed = run(args);
    kill_at_checkpoint(0);
    EXPECT_EQ(killed.exit_code, -1) << "the design ended before it could be killed: " << killed.err;
    ASSERT_EQ(checkpoint_step(folder), before + steps);
  }
  std::string mission_;
};

TEST_F(design_command, KilledTwiceAndResumedItEndsExactlyAsAnUninterruptedRun) {
  const std::string uninterrupted = run_ok(design_args("whole", 1500, 7, 2));
  ASSERT_FALSE(uninterrupted.empty());

  const auto folder = scratch() / "killed";
  kill_after(design_args("killed", 1500, 7, 2), folder, 15);
  const std::int64_t first_kill = checkpoint_step(folder);
  // The resumed process gets the stored settings only; a second kill lands mid-race as well.
  kill_after({"design", "--resume", folder.string(), "--threads", "2", "--json"}, folder, 25);
  EXPECT_GT(checkpoint_step(folder), first_kill);
  const std::string resumed = run_ok({"design", "--resume", folder.string(), "--threads", "1", "--json"});

  EXPECT_EQ(design_outcome(resumed), design_outcome(uninterrupted));
  EXPECT_TRUE(nlohmann::json::parse(resumed).at("resumed").get<bool>());
  // Every experiment is stored once, in the order an uninterrupted run stores it.
  EXPECT_EQ(experiment_log(folder), experiment_log(scratch() / "whole"));
  storage::Database db(folder / "design.db", false);
  auto count = db.prepare("SELECT count(*) FROM experiments");
  count.step();
  EXPECT_EQ(count.integer(0), nlohmann::json::parse(resumed).at("experiments_used").get<std::int64_t>());
}

TEST_F(design_command, TheResultDoesNotDependOnTheThreadCount) {
  const std::string one = run_ok(design_args("one", 1100, 3, 1));
  const std::string two = run_ok(design_args("two", 1100, 3, 2));
  EXPECT_EQ(design_outcome(one), design_outcome(two));
  EXPECT_EQ(experiment_log(scratch() / "one"), experiment_log(scratch() / "two"));
}

TEST_F(design_command, FoldersThatHoldNoResumableDesignAreRefused) {
  const auto empty = scratch() / "empty";
  std::filesystem::create_directories(empty);
  expect_error(run({"design", "--resume", empty.string()}), 1, "is not a design folder");
  expect_error(run({"design", "--resume", (scratch() / "missing").string()}), 1, "is not a folder");

  const auto garbage = scratch() / "garbage";
  std::filesystem::create_directories(garbage);
  std::ofstream(garbage / "design.db") << "this is not a database, just text that lost its way\n";
  expect_error(run({"design", "--resume", garbage.string()}), 1, "damaged");

  const auto foreign = scratch() / "foreign";
  std::filesystem::create_directories(foreign);
  storage::Database(foreign / "design.db").execute("CREATE TABLE notes (text TEXT)");
  expect_error(run({"design", "--resume", foreign.string()}), 1, "not a SwarmDesign design database");

  const auto finished = scratch() / "finished";
  const std::string made = run_ok(design_args("finished", 1100, 5, 2));
  // A finished design asked for again answers as run-design does (issue #54): its result, exit
  // 0, whether resumed by folder or asked with the settings it was made with; the same design.
  const std::string resumed = run_ok({"design", "--resume", finished.string(), "--json"});
  EXPECT_EQ(design_outcome(resumed), design_outcome(made));
  auto again = design_args("finished", 1100, 5, 2);
  std::erase(again, std::string("--json"));
  EXPECT_NE(run_ok(again).find("has already finished"), std::string::npos);
  expect_error(run(design_args("finished", 1100, 6, 2)), 1, "was started with other settings (mission ");

  storage::Database(finished / "design.db").execute("UPDATE meta SET value = '99' WHERE key = 'format_version'");
  expect_error(run({"design", "--resume", finished.string()}), 1, "format version 99");
  storage::Database(finished / "design.db").execute("UPDATE meta SET value = '1' WHERE key = 'format_version'");
  storage::Database(finished / "design.db").execute("UPDATE checkpoint SET state = '{\"truncated\": ' WHERE id = 1");
  expect_error(run({"design", "--resume", finished.string()}), 1, "cannot be read");
}

TEST_F(design_command, AMissionFileEditedSinceTheDesignStartedIsRefused) {
  const auto folder = scratch() / "edited";
  kill_after(design_args("edited", 1100, 4, 2), folder, 3);
  std::stringstream original;
  original << std::ifstream(mission_).rdbuf();
  std::ofstream(mission_) << std::regex_replace(original.str(), std::regex("\"duration\": *[0-9.]+"), "\"duration\": 12");
  expect_error(run({"design", "--resume", folder.string()}), 1, "has changed since the design");
  // A new description changes no run, so the design goes on.
  std::ofstream(mission_) << std::regex_replace(original.str(), std::regex("\"description\": *\"[^\"]*\""),
                                                "\"description\": \"the same mission, described anew\"");
  const std::string resumed = run_ok({"design", "--resume", folder.string(), "--json"});
  EXPECT_TRUE(nlohmann::json::parse(resumed).at("resumed").get<bool>());
}

TEST_F(design_command, ADesignRunByASimulatorThatScoresDifferentlyIsRefused) {
  const auto folder = scratch() / "older";
  kill_after(design_args("older", 1100, 4, 2), folder, 3);
  storage::Database db(folder / "design.db");
  const std::string current = [&] {
    auto q = db.prepare("SELECT value FROM meta WHERE key = 'results_version'");
    return q.step() ? q.text(0) : std::string();
  }();
  EXPECT_EQ(current, std::to_string(kResultsVersion));
  // Designs made before the version was kept count as version 1.
  db.execute("DELETE FROM meta WHERE key = 'results_version'");
  expect_error(run({"design", "--resume", folder.string()}), 1, "results version 1, this one " + current);
  // Version 4 heard neighbours within 0.8 m on the catalogue's missions: its designs stop too.
  db.execute("INSERT INTO meta (key, value) VALUES ('results_version', '4')");
  expect_error(run({"design", "--resume", folder.string()}), 1, "results version 4, this one " + current);
  // Those of this version go on.
  db.execute("UPDATE meta SET value = '" + current + "' WHERE key = 'results_version'");
  const std::string resumed = run_ok({"design", "--resume", folder.string(), "--json"});
  EXPECT_TRUE(nlohmann::json::parse(resumed).at("resumed").get<bool>());
}

TEST_F(design_command, BadRequestsGetOneLineErrors) {
  const auto minimum =
      run({"design", "--mission", mission_, "--budget", "300", "--fsm", "--chocolate", "--out", (scratch() / "x").string()});
  expect_error(minimum, 2, "below the minimum of 1008");
  expect_error(run({"design", "--mission", mission_, "--budget", "-5"}), 2, "positive integer");
  expect_error(run({"design", "--mission", mission_, "--budget", "ten"}), 2, "positive integer");
  expect_error(run({"design", "--mission", "no-such-mission", "--budget", "2000"}), 2, "unknown mission");
  expect_error(run({"design", "--mission", mission_, "--budget", "200", "--bt", "--maple"}), 2, "below the minimum");
  expect_error(run({"design", "--budget", "2000"}), 2, "--mission is required");
  expect_error(run({"design", "--resume", scratch().string(), "--budget", "2000"}), 2, "--resume");
  EXPECT_FALSE(std::filesystem::exists(scratch() / "x"));
}

TEST_F(design_command, ShowsProgressOnATerminalAndTheBestControlSoftwareAtTheEnd) {
  const auto on_terminal = run_swarmdesign_on_terminal(
      {"design", "--mission", mission_, "--budget", "1100", "--seed", "2", "--fsm", "--chocolate", "--out",
       (scratch() / "tty").string()},
      {},
      environment());
  EXPECT_EQ(on_terminal.exit_code, 0) << on_terminal.out;
  EXPECT_NE(on_terminal.out.find("iteration 1/"), std::string::npos) << on_terminal.out;
  EXPECT_NE(on_terminal.out.find("alive "), std::string::npos);
  EXPECT_NE(on_terminal.out.find("Finite-state machine"), std::string::npos);
  EXPECT_NE(on_terminal.out.find("Configuration string:"), std::string::npos);

  // Piped, the same design prints no progress, and the configuration string it reports is
  // control software that `evaluate` accepts.
  const auto piped = run({"design", "--mission", mission_, "--budget", "1100", "--seed", "2", "--fsm", "--chocolate", "--out",
                          (scratch() / "pipe").string()});
  EXPECT_EQ(piped.exit_code, 0);
  EXPECT_EQ(piped.err, "");
  const std::string marker = "Configuration string:\n  ";
  const auto at = piped.out.find(marker);
  ASSERT_NE(at, std::string::npos) << piped.out;
  const auto begin = at + marker.size();
  const std::string line = piped.out.substr(begin, piped.out.find('\n', begin) - begin);
  std::vector<std::string> args{"evaluate", "--mission", mission_, "--seed", "5"};
  std::istringstream tokens(line);
  for (std::string t; tokens >> t;) args.push_back(t);
  EXPECT_NE(run_ok(args).find("Score "), std::string::npos);
}

}  // namespace
}  // namespace sd::test
