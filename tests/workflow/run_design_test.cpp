// The design part of the project workflow, driven through the real binary: run-design in the
// foreground and detached, status while it runs, test-design, a killed design resumed by
// run-design, and requests that must change nothing.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <sstream>

#include "sanitized.hpp"
#include "storage/sqlite.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;

class run_design : public WorkflowTest {
 protected:
  void SetUp() override {
    WorkflowTest::SetUp();
    mission_ = write_short_mission(scratch()).string();
  }
  void project_with_budget(int budget) {
    user_with_active_project("alice", "swarm");
    run_ok({"set-mission", mission_});
    run_ok({"set-budget", std::to_string(budget)});
  }
  json status() { return json::parse(run_ok({"status", "--json"})); }
  std::filesystem::path design_folder(int id) const {
    return home() / "users" / "alice" / "projects" / "swarm" / "designs" / std::to_string(id);
  }
  std::string mission_;
};

int count_lines_starting(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  int n = 0;
  for (std::string line; std::getline(lines, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

TEST_F(run_design, TheWholeWorkflowFromSignUpToATestedDesign) {
  // A usual umask, which would leave folders 0755 and files 0644: the CLI makes the home
  // private whatever it is, as the server does (the CLI processes inherit it).
  const mode_t umask_before = ::umask(022);
  project_with_budget(1100);
  EXPECT_NE(run_ok({"status"}).find("no design yet"), std::string::npos);
  const std::string out = run_ok({"run-design", "--fsm", "--chocolate", "--seed", "3", "--threads", "2"});
  EXPECT_NE(out.find("Configuration string:"), std::string::npos) << out;
  EXPECT_NE(out.find("test-design"), std::string::npos);

  const json s = status();
  EXPECT_EQ(s["design"]["state"], "finished");
  EXPECT_EQ(s["design"]["seed"], 3);
  const json& p = s["progress"];
  EXPECT_GT(p["experiments_used"].get<int>(), 1000);
  EXPECT_LE(p["experiments_used"].get<int>(), 1100);
  EXPECT_EQ(p["remaining_budget"].get<int>(), 1100 - p["experiments_used"].get<int>());
  EXPECT_GE(p["total_iterations"].get<int>(), p["iteration"].get<int>());
  ASSERT_TRUE(p["best"].is_object());
  // The designs table keeps the same best control software that status reads from design.db.
  EXPECT_EQ(query("SELECT best_config FROM designs"), p["best"]["configuration"].get<std::string>());
  EXPECT_NE(out.find(p["best"]["configuration"].get<std::string>()), std::string::npos);

  const json complete = json::parse(run_ok({"status", "--complete", "--json"}));
  const json& log = complete["race_log"];
  ASSERT_EQ(log.size(), static_cast<std::size_t>(p["iteration"].get<int>()));
  long long raced = 0;
  for (const json& race : log) {
    EXPECT_FALSE(race["instances"].empty());
    EXPECT_FALSE(race["elites"].empty()) << race.dump();
    for (const json& c : race["configurations"]) raced += c["runs"].get<long long>();
  }
  EXPECT_EQ(raced, p["experiments_used"].get<long long>());  // every run belongs to one race
  EXPECT_EQ(log.back()["elites"][0], p["best"]["id"]);
  EXPECT_NE(run_ok({"status", "--complete"}).find("eliminated after"), std::string::npos);

  // test-design: the best design by default, or any control software; thesis spelling too.
  const std::string tested = run_ok({"test-design", "--seeds", "1-3"});
  EXPECT_EQ(count_lines_starting(tested, "Score "), 3) << tested;
  EXPECT_EQ(count_lines_starting(tested, "Mean "), 1);
  const std::string given = run_ok({"testDesign", "--seeds", "4-5", "--fsm-config", "--nstates", "1", "--s0", "10", "--rwm0", "5"});
  EXPECT_EQ(count_lines_starting(given, "Score "), 2) << given;

  ::umask(umask_before);
  const auto mode = [](const std::filesystem::path& path) {
    struct stat info {};
    EXPECT_EQ(::lstat(path.c_str(), &info), 0) << path;
    return info.st_mode & 0777;
  };
  EXPECT_EQ(mode(design_folder(1)), 0700u);
  EXPECT_EQ(mode(design_folder(1) / "design.db"), 0600u);
  for (const auto& entry : std::filesystem::recursive_directory_iterator(home())) {
    EXPECT_EQ(mode(entry.path()) & 077, 0u) << entry.path() << " is open to others";
  }
}

TEST_F(run_design, AnEarlierDesignIsShownAndDeletedByItsNumberAndAProjectWhole) {
  project_with_budget(1100);
  run_ok({"run-design", "--fsm", "--chocolate", "--seed", "3", "--threads", "2"});
  run_ok({"run-design", "--fsm", "--chocolate", "--seed", "4", "--threads", "2"});
  EXPECT_EQ(status()["design"]["id"], 2);
  const json first = json::parse(run_ok({"status", "--design", "1", "--json"}));
  EXPECT_EQ(first["design"]["id"], 1);
  EXPECT_EQ(first["design"]["seed"], 3);
  EXPECT_EQ(first["progress"]["best"]["configuration"].get<std::string>(), query("SELECT best_config FROM designs WHERE id = 1"));
  expect_error(run({"status", "--design", "9"}), 1, "has no design 9");

  // Without a terminal to ask on, nothing is deleted unless --yes says so.
  expect_error(run({"delete-design", "1"}), 2, "confirm with --yes");
  EXPECT_TRUE(std::filesystem::is_directory(design_folder(1)));
  EXPECT_NE(run_ok({"delete-design", "1", "--yes"}).find("Deleted design 1."), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(design_folder(1)));
  EXPECT_TRUE(std::filesystem::is_directory(design_folder(2)));
  EXPECT_EQ(query("SELECT group_concat(id) FROM designs"), "2");
  expect_error(run({"delete-design", "1", "--yes"}), 1, "has no design 1");
  EXPECT_EQ(status()["design"]["id"], 2);

  // Another user's attempt reads as a project that does not exist, and deletes nothing.
  sign_up("bob", "another good password");
  sign_in("bob", "another good password");
  expect_error(run({"delete-project", "swarm", "--yes"}), 1, "no project named 'swarm'");
  expect_error(run({"delete-design", "2", "--yes", "--project", "swarm"}), 1, "no project named 'swarm'");
  sign_in("alice", "alice-secret-pw");

  expect_error(run({"delete-project", "swarm"}), 2, "confirm with --yes");
  EXPECT_NE(run_ok({"delete-project", "swarm", "--yes", "--json"}).find("\"deleted\": \"swarm\""), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(design_folder(2).parent_path().parent_path()));
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
  expect_error(run({"status"}), 1, "no active project");
}

TEST_F(run_design, StatusReadsADetachedDesignWhileItRuns) {
  // Long enough to be still running when the refusals below are tried (race steps now go out
  // in wider batches, and a 4000-run design could end between the status read and them in
  // Release). Under a sanitizer each run takes about ten times longer, so a tenth of the runs
  // lasts as long; reads_while_running below checks that it did. Runs of 10 s there too: the
  // sanitizer trees' shorter default would end it four times sooner.
  write_short_mission(scratch(), 10);
  project_with_budget(kSanitized ? 4000 : 30000);
  const auto started = run({"run-design", "--detach", "--fsm", "--chocolate", "--seed", "1", "--threads", "1"});
  ASSERT_EQ(started.exit_code, 0) << started.err;
  EXPECT_NE(started.out.find("swarmdesign status"), std::string::npos) << started.out;
  EXPECT_NE(started.out.find("design.log"), std::string::npos);

  ASSERT_TRUE(wait_until([&] { return checkpoint_step(design_folder(1)) > 5; }, 60s));
  long long previous = 0;
  int reads_while_running = 0;
  for (int i = 0; i < 40; ++i) {
    const auto outcome = run({"status", "--json"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;  // never "database is locked"
    const json s = json::parse(outcome.out);
    const long long used = s["progress"]["experiments_used"].get<long long>();
    EXPECT_GE(used, previous);
    previous = used;
    if (s["design"]["state"] != "running") break;
    ++reads_while_running;
    EXPECT_GT(s["progress"]["race_configurations"].get<int>(), 0);
    EXPECT_GT(s["progress"]["race_budget"].get<int>(), 0);
  }
  EXPECT_GT(reads_while_running, 3);
  if (status()["design"]["state"] == "running") {
    expect_error(run({"run-design"}), 1, "is still running");
    // Nor can the account-free command write into the running design's folder.
    expect_error(run({"design", "--resume", design_folder(1).string()}), 1, "being run by another process");
  }
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "1");

  // The rest of the runs: seconds in Release and under the sanitizers' builds.
  ASSERT_TRUE(wait_until([&] { return status()["design"]["state"] != "running"; }, 900s));
  const json done = status();
  EXPECT_EQ(done["design"]["state"], "finished");
  EXPECT_EQ(query("SELECT best_config FROM designs"), done["progress"]["best"]["configuration"].get<std::string>());
}

TEST_F(run_design, AKilledDesignIsResumedByRunDesignAndEndsAsIfNeverStopped) {
  const std::string reference = run_ok({"design", "--mission", mission_, "--budget", "1500", "--seed", "7", "--threads",
                                        "2", "--fsm", "--chocolate", "--out", (scratch() / "reference").string(), "--json"});
  project_with_budget(1500);
  kill_at_checkpoint(15);  // the detached design SIGKILLs itself right after checkpoint 15
  run_ok({"run-design", "--detach", "--fsm", "--chocolate", "--seed", "7", "--threads", "2"});
  kill_at_checkpoint(0);
  ASSERT_TRUE(wait_until([&] { return status()["design"]["state"] == "interrupted"; }, 60s));
  EXPECT_EQ(checkpoint_step(design_folder(1)), 15);
  EXPECT_NE(run_ok({"status"}).find("run-design"), std::string::npos);

  const std::string resumed = run_ok({"run-design", "--threads", "1"});
  EXPECT_NE(resumed.find("resuming"), std::string::npos) << resumed;
  const json s = status();
  EXPECT_EQ(s["design"]["state"], "finished");
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "1");
  const json expected = json::parse(reference);
  EXPECT_EQ(query("SELECT best_config FROM designs"), expected["best"]["configuration"].get<std::string>());
  // (query() reads the REAL back as text with 15 digits; the log comparison below is exact.)
  EXPECT_NEAR(std::stod(query("SELECT best_score FROM designs")), expected["best"]["mean_score"].get<double>(), 1e-9);
  EXPECT_EQ(experiment_log(design_folder(1)), experiment_log(scratch() / "reference"));
}

TEST_F(run_design, AnInterruptedDesignThatCannotBeResumedIsGivenUpWithNew) {
  project_with_budget(1100);
  kill_at_checkpoint(3);
  run_ok({"run-design", "--detach", "--fsm", "--chocolate", "--seed", "7", "--threads", "2"});
  kill_at_checkpoint(0);
  ASSERT_TRUE(wait_until([&] { return status()["design"]["state"] == "interrupted"; }, 60s));
  // As after an upgrade whose simulator scores differently: resuming would mix two simulators.
  storage::Database(design_folder(1) / "design.db").execute("UPDATE meta SET value = '1' WHERE key = 'results_version'");

  const Outcome refused = run({"run-design"});
  expect_error(refused, 1, "design 1 of swarm was interrupted and cannot be resumed");
  EXPECT_NE(refused.err.find("run-design --new"), std::string::npos) << refused.err;
  EXPECT_EQ(status()["design"]["state"], "interrupted");

  const std::string fresh = run_ok({"run-design", "--new", "--fsm", "--chocolate", "--seed", "8", "--threads", "2"});
  EXPECT_NE(fresh.find("Design 1 of swarm is given up (failed)"), std::string::npos) << fresh;
  EXPECT_EQ(query("SELECT group_concat(state) FROM (SELECT state FROM designs ORDER BY id)"), "failed,finished");
  EXPECT_TRUE(std::filesystem::exists(design_folder(1) / "design.db")) << "the given-up design's data stays";
  EXPECT_EQ(status()["design"]["state"], "finished");
}

TEST_F(run_design, RefusedRequestsChangeNothing) {
  user_with_active_project("alice", "swarm");
  const std::string before = snapshot();
  expect_error(run({"run-design"}), 1, "has no mission");
  run_ok({"set-mission", mission_});
  expect_error(run({"run-design"}), 1, "has no budget");
  run_ok({"set-budget", "500"});
  const std::string configured = snapshot();
  expect_error(run({"run-design", "--fsm", "--chocolate"}), 2, "below the minimum of 1008");
  expect_error(run({"run-design"}), 2, "below the minimum");  // all flavours, both architectures
  run_ok({"set-budget", "1200"});
  const std::string ready = snapshot();
  expect_error(run({"run-design", "--bt", "--fsm"}), 2, "below the minimum");
  expect_error(run({"run-design", "--seed", "x"}), 2, "seed 'x'");
  EXPECT_EQ(snapshot(), ready);
  expect_error(run({"test-design"}), 1, "no finished design yet");  // a state, not a malformed request
  expect_error(run({"test-design", "--fsm-config", "--nstates", "9"}), 2, "nstates");
  EXPECT_EQ(snapshot(), ready);
  EXPECT_NE(before, configured);
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
}

TEST_F(run_design, ARobustDesignIsAssessedByIdOnSamplesItNeverSaw) {
  project_with_budget(1100);
  const std::string out = run_ok({"run-design", "--fsm", "--chocolate", "--seed", "3", "--threads", "2",
                                  "--pseudo-reality", "sampled-around", "--pseudo-reality-samples", "101-103"});
  EXPECT_NE(out.find("A robust design"), std::string::npos) << out;
  // The same command again finds it finished (spelt as the flag first was: the alias holds for
  // one release); with other samples it is another design.
  EXPECT_NE(run_ok({"run-design", "--fsm", "--chocolate", "--seed", "3", "--pseudo-realities", "sampled-around",
                    "--pseudo-reality-samples", "101-103"}).find("already finished"), std::string::npos);
  const json by_id = json::parse(run_ok({"assess", "--project-design", "1", "--samples", "1-2", "--seeds", "1-3", "--json"}));
  const json by_folder =
      json::parse(run_ok({"assess", "--design", design_folder(1).string(), "--samples", "1-2", "--seeds", "1-3", "--json"}));
  ASSERT_EQ(by_id["software"].size(), 1u);
  EXPECT_EQ(by_id["software"][0]["label"], "design 1 best");
  EXPECT_EQ(by_id["software"][0]["runs"], by_folder["software"][0]["runs"]);
  EXPECT_EQ(by_id["software"][0]["control_software"], status()["design"]["best_configuration"]);
  EXPECT_EQ(by_id["samples"], json::array({1, 2}));
}

}  // namespace
}  // namespace sd::test
