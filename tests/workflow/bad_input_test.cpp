// Every kind of bad input gets one clear error line, the contract's exit status (2 misuse,
// 1 refused work) and leaves the database, the files and the session exactly as they were.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

struct BadInput {
  std::vector<std::string> args;
  std::string input;
  int exit_code;
  std::string message;
};

class workflow_bad_input : public WorkflowTest {
 protected:
  /// Runs every case against the same state and checks that none of them changes it.
  void expect_all_refused(const std::vector<BadInput>& cases) {
    const std::string before = snapshot();
    for (const auto& bad : cases) {
      std::string command;
      for (const auto& arg : bad.args) command += " [" + arg + "]";
      SCOPED_TRACE("swarmdesign" + command);
      expect_error(run(bad.args, bad.input), bad.exit_code, bad.message);
      ASSERT_EQ(snapshot(), before) << "the refused command changed the state";
    }
  }

  /// Alice signed in with her project p1 active; Bob has a project of his own.
  void alice_and_bob() {
    sign_up("bob", "another good password");
    sign_in("bob", "another good password");
    run_ok({"new-project", "bobs-project"});
    user_with_active_project("alice", "p1");
    run_ok({"set-budget", "1000"});
    run_ok({"set-mission", "aac"});
  }
};

TEST_F(workflow_bad_input, AccountsRefuseWrongPasswordsUnknownUsersDuplicatesAndWeakPasswords) {
  alice_and_bob();
  expect_all_refused({
      {{"sign-in", "alice", "--password-stdin"}, "not her password\n", 1, "wrong user name or password"},
      {{"sign-in", "bob", "--password-stdin"}, "\n", 1, "wrong user name or password"},
      {{"sign-in", "nobody", "--password-stdin"}, "whatever password\n", 1, "wrong user name or password"},
      {{"sign-up", "alice", "--password-stdin"}, "a fine password\n", 1, "user name 'alice' is already taken"},
      {{"sign-up", "ALICE", "--password-stdin"}, "a fine password\n", 1, "already taken"},
      {{"sign-up", "carol", "--password-stdin"}, "short\n", 2, "at least 8 characters"},
      {{"sign-up", "carol", "--password-stdin"}, "\n", 2, "password is empty"},
      {{"sign-up", "carol", "--password-stdin"}, "", 2, "no password given on standard input"},
      {{"sign-up", "carolcarol", "--password-stdin"}, "carolcarol\n", 2, "must not be the user name"},
      {{"sign-up", "carol"}, "a fine password\n", 2, "not a terminal; to pass the password on standard input use --password-stdin"},
      {{"sign-up", "9lives", "--password-stdin"}, "a fine password\n", 2, "user name '9lives' is not valid"},
      {{"sign-up", "a/b", "--password-stdin"}, "a fine password\n", 2, "is not valid"},
      {{"sign-up", "", "--password-stdin"}, "a fine password\n", 2, "user name is empty"},
      {{"sign-in", "../alice", "--password-stdin"}, "a fine password\n", 2, "is not valid"},
      {{"sign-up"}, "", 2, "USER is required"},
  });
}

TEST_F(workflow_bad_input, ProjectsRefuseUnknownForeignDuplicateAndInvalidNames) {
  alice_and_bob();
  expect_all_refused({
      {{"select-project", "nope"}, "", 1, "no project named 'nope'"},
      {{"select-project", "bobs-project"}, "", 1, "no project named 'bobs-project'"},
      {{"select-project", "../p1"}, "", 2, "project name '../p1' is not valid"},
      {{"new-project", "p1"}, "", 1, "you already have a project named 'p1'"},
      {{"new-project", "P1"}, "", 1, "already have a project"},
      {{"new-project", "a/b"}, "", 2, "project name 'a/b' is not valid"},
      {{"new-project", ""}, "", 2, "project name is empty"},
      {{"new-project", ".hidden"}, "", 2, "is not valid"},
      {{"new-project", ".."}, "", 2, "is not valid"},
      {{"new-project", "has space"}, "", 2, "is not valid"},
      {{"new-project", std::string(65, 'x')}, "", 2, "longer than 64 characters"},
      {{"new-project", "c", "--cluster", "hpc.example.org"}, "", 2, "--cluster requires --cluster-user"},
      {{"new-project", "c", "--cluster-user", "al"}, "", 2, "--cluster-user requires --cluster"},
      {{"new-project", "c", "--cluster=-oProxyCommand=x", "--cluster-user", "al"}, "", 2, "is not a host name"},
      {{"new-project", "c", "--cluster", "bad host", "--cluster-user", "al"}, "", 2, "is not a host name"},
      {{"new-project", "c", "--cluster", "hpc.example.org", "--cluster-user=-x"}, "", 2, "cluster user '-x' is not valid"},
      {{"no-such-command"}, "", 2, "see --help"},
  });
}

TEST_F(workflow_bad_input, BudgetMustBeAPositiveInteger) {
  alice_and_bob();
  std::vector<BadInput> cases;
  for (const char* budget : {"0", "-5", "abc", "1.5", "1e5", "+7", " 12", "12 ", "", "99999999999999999999"})
    cases.push_back({{"set-budget", budget}, "", 2, "expected a positive integer"});
  cases.push_back({{"set-budget"}, "", 2, "N is required"});
  expect_all_refused(cases);
}

TEST_F(workflow_bad_input, MissionMustBeInTheCatalogue) {
  alice_and_bob();
  expect_all_refused({
      // An unknown name is a malformed request (exit 2), the same for set-mission as for evaluate.
      {{"set-mission", "no-such-mission"}, "", 2, "unknown mission 'no-such-mission'"},
      {{"set-mission"}, "no-such-mission\n", 2, "unknown mission 'no-such-mission'"},
      {{"set-mission"}, "99\n", 2, "there is no mission number 99"},
      {{"set-mission"}, "", 2, "no mission chosen"},
      {{"set-mission"}, "\n", 2, "no mission chosen"},
  });
}

TEST_F(workflow_bad_input, FilesTheCliReadsAreRegularBoundedAndNeverQuoted) {
  alice_and_bob();
  // On one's own machine any readable file may be named, but a device or a FIFO is not read
  // (it would never end or never answer), nor a file over 1 MiB, and a parse error says where
  // without quoting what it read.
  const auto big = scratch() / "big.json";
  std::ofstream(big) << "{\"name\": \"" << std::string(2 << 20, 'x') << "\"}";
  const auto fifo = scratch() / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto typo = scratch() / "typo.json";
  std::ofstream(typo) << "{\n  \"name\": \"hunter2-secret\",\n  oops\n}";
  const auto config = scratch() / "fsm.txt";
  std::ofstream(config) << std::string(2 << 20, ' ');
  expect_all_refused({
      {{"set-mission", "/dev/zero"}, "", 2, "mission file /dev/zero is not a regular file"},
      {{"set-mission", "/dev/urandom"}, "", 2, "is not a regular file"},
      {{"set-mission", fifo.string()}, "", 2, "is not a regular file"},
      {{"set-mission", scratch().string() + "/"}, "", 2, "is not a regular file"},
      {{"set-mission", big.string()}, "", 2, "is larger than 1 MiB"},
      {{"set-mission", typo.string()}, "", 2, "(line 3, column 3)"},
      {{"evaluate", "--mission", "/dev/zero", "--seed", "1", "--fsm-config", "--nstates", "1", "--s0", "0"}, "", 2,
       "is not a regular file"},
      {{"evaluate", "--mission", "aac", "--seed", "1", "--config-file", "/dev/zero"}, "", 2, "is not a regular file"},
      {{"evaluate", "--mission", "aac", "--seed", "1", "--config-file", config.string()}, "", 2, "larger than 1 MiB"},
  });
  const std::string said = run({"set-mission", typo.string()}).err;
  EXPECT_EQ(said.find("hunter2"), std::string::npos) << said;
  EXPECT_EQ(said.find("oops"), std::string::npos) << said;
}

TEST_F(workflow_bad_input, EveryProjectCommandNeedsASignedInUser) {
  alice_and_bob();
  run_ok({"exit"});
  std::vector<BadInput> cases;
  for (const auto& args : std::vector<std::vector<std::string>>{{"new-project", "x"},
                                                                {"show-projects"},
                                                                {"select-project", "p1"},
                                                                {"active-project"},
                                                                {"set-budget", "10"},
                                                                {"set-mission", "aac"}})
    cases.push_back({args, "", 1, "not signed in; sign in with: swarmdesign sign-in USER"});
  expect_all_refused(cases);
}

TEST_F(workflow_bad_input, SettingsNeedAnActiveProject) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  run_ok({"new-project", "p1"});  // but not selected
  expect_all_refused({
      {{"active-project"}, "", 1, "no active project; choose one with: swarmdesign select-project NAME"},
      {{"set-budget", "10"}, "", 1, "no active project"},
      {{"set-mission", "aac"}, "", 1, "no active project"},
      {{"set-mission"}, "1\n", 1, "no active project"},
  });
}

}  // namespace
}  // namespace sd::test
