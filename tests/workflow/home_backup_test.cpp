// A lab's home backed up while a design runs, restored into another home, and that design
// resumed there to the very result of the uninterrupted one (issue #56); damaged archives and
// planted links refused or reported in one line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <set>
#include <thread>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class home_backup : public WorkflowTest {
 protected:
  /// The same command against another home.
  Outcome run_in(const fs::path& other, const std::vector<std::string>& args, const std::string& input = "") {
    Environment environment = this->environment();
    environment.set["SWARMDESIGN_HOME"] = other.string();
    return run_swarmdesign(args, input, environment);
  }
};

TEST_F(home_backup, ABackupTakenWhileADesignRunsRestoresElsewhereAndTheDesignResumesToTheSameResult) {
  user_with_active_project("alice", "lab");
  // The mission file lives in the project, named by the home's absolute path: it must follow.
  const fs::path mission = write_short_mission(home() / "users" / "alice" / "projects" / "lab", 4);
  run_ok({"set-mission", mission.string()});
  // Long enough that the backup, taken at the fourth checkpoint, is over well before the design.
  run_ok({"set-budget", "4000"});
  const json reference = json::parse(run_ok({"design", "--mission", mission.string(), "--budget", "4000", "--fsm",
                                             "--chocolate", "--seed", "3", "--threads", "1", "--out",
                                             (scratch() / "reference").string(), "--json"}));

  const std::vector<std::string> start{"run-design", "--fsm", "--chocolate", "--seed", "3", "--threads", "1"};
  const int pid = start_swarmdesign(start, environment(), (scratch() / "out").string(), (scratch() / "err").string());
  const fs::path folder = home() / "users" / "alice" / "projects" / "lab" / "designs" / "1";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (checkpoint_step(folder) < 4 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_GE(checkpoint_step(folder), 4) << "the design never reached its fourth checkpoint";
  const fs::path archive = scratch() / "lab.tar.gz";
  const json backup = json::parse(run_ok({"admin", "backup", archive.string(), "--json"}));
  EXPECT_EQ(backup["from"], home().string());
  ASSERT_EQ(wait_swarmdesign(pid), 0) << "the design went on to its end in its own home";
  ASSERT_EQ(query("SELECT state FROM designs WHERE id = 1"), "finished");

  const fs::path elsewhere = scratch() / "restored-home";
  const json restored = json::parse(run_ok({"admin", "restore", archive.string(), "--into", elsewhere.string(), "--json"}));
  EXPECT_EQ(restored["check"]["ok"], true) << restored.dump();
  EXPECT_EQ(restored["check"]["designs"], 1);
  EXPECT_FALSE(fs::exists(elsewhere / "session")) << "a backup carries no one's sign-in";
  EXPECT_EQ(fs::status(elsewhere).permissions() & fs::perms::all, fs::perms::owner_all);

  // There the design is the one the backup caught mid-race: interrupted, it resumes to the end.
  const Outcome signed_in = run_in(elsewhere, {"sign-in", "alice", "--password-stdin"}, "alice-secret-pw\n");
  ASSERT_EQ(signed_in.exit_code, 0) << signed_in.err;
  const Outcome resumed = run_in(elsewhere, start);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resuming"), std::string::npos) << resumed.out;
  const fs::path moved = elsewhere / "users" / "alice" / "projects" / "lab" / "designs" / "1";
  EXPECT_EQ(experiment_log(moved), experiment_log(scratch() / "reference"));
  const Outcome status = run_in(elsewhere, {"status", "--json"});
  ASSERT_EQ(status.exit_code, 0) << status.err;
  EXPECT_NE(status.out.find(reference["best"]["configuration"].get<std::string>()), std::string::npos) << status.out;
  // Its mission is the restored home's own file now, not the old home's.
  const Outcome projects = run_in(elsewhere, {"show-projects", "--json"});
  EXPECT_NE(projects.out.find(elsewhere.string()), std::string::npos) << projects.out;
}

TEST_F(home_backup, ADamagedOrForeignArchiveIsRefusedInOneLineAndNothingIsRestored) {
  user_with_active_project("bob", "p");
  const fs::path archive = scratch() / "b.tar.gz";
  run_ok({"admin", "backup", archive.string()});
  // One byte changed in the middle of the compressed stream.
  std::string bytes;
  {
    std::ifstream in(archive, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
  const fs::path damaged = scratch() / "damaged.tar.gz";
  std::ofstream(damaged, std::ios::binary) << bytes;
  expect_error(run({"admin", "restore", damaged.string(), "--into", (scratch() / "h1").string()}), 1, "restore:");
  EXPECT_FALSE(fs::exists(scratch() / "h1"));
  const fs::path foreign = scratch() / "foreign.tar.gz";
  std::ofstream(foreign) << "not an archive at all";
  expect_error(run({"admin", "restore", foreign.string(), "--into", (scratch() / "h2").string()}), 1, "restore:");
  EXPECT_FALSE(fs::exists(scratch() / "h2"));
  // Never over a home in use.
  expect_error(run({"admin", "restore", archive.string(), "--into", home().string()}), 1, "is not empty");
  EXPECT_EQ(query("SELECT count(*) FROM users"), "1");
}

TEST_F(home_backup, TheCheckReportsPlantedLinksAndFoldersTheDatabaseDoesNotName) {
  user_with_active_project("carol", "p");
  EXPECT_NE(run_ok({"admin", "check"}).find("no problem"), std::string::npos);
  const fs::path project = home() / "users" / "carol" / "projects" / "p";
  fs::create_symlink("/etc/passwd", project / "assessment.json");
  fs::create_directories(home() / "users" / "carol" / "projects" / "ghost");
  const Outcome checked = run({"admin", "check", "--json"});
  EXPECT_EQ(checked.exit_code, 1);
  const json doc = json::parse(checked.out);
  EXPECT_EQ(doc["ok"], false);
  std::set<std::string> kinds;
  for (const json& p : doc["problems"]) kinds.insert(p["kind"].get<std::string>() + " " + p["what"].get<std::string>());
  EXPECT_TRUE(kinds.count("link users/carol/projects/p/assessment.json")) << doc.dump();
  EXPECT_TRUE(kinds.count("orphan-folder users/carol/projects/ghost")) << doc.dump();
  // A backup never carries the link.
  const fs::path archive = scratch() / "c.tar.gz";
  run_ok({"admin", "backup", archive.string()});
  const fs::path restored = scratch() / "c-home";
  run({"admin", "restore", archive.string(), "--into", restored.string()});
  EXPECT_FALSE(fs::exists(fs::symlink_status(restored / "users" / "carol" / "projects" / "p" / "assessment.json")));
}

}  // namespace
}  // namespace sd::test
