// Accounts end to end: what sign-up stores, what sign-in leaves on disk, sign-out, expiry.
// Suites are named workflow_* so that `ctest -R workflow` runs them all.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "storage/clock.hpp"
#include "storage/sqlite.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using workflow_accounts = WorkflowTest;

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

TEST_F(workflow_accounts, SignUpStoresOnlyAnArgon2idHashWithInteractiveLimits) {
  const std::string password = "correct horse battery";
  const std::string out = run_ok({"sign-up", "alice", "--password-stdin"}, password + "\n");
  EXPECT_NE(out.find("Created user alice"), std::string::npos);

  const std::string hash = query("SELECT password_hash FROM users WHERE name = 'alice'");
  EXPECT_EQ(hash.rfind("$argon2id$", 0), 0u) << hash;
  EXPECT_NE(hash.find("m=65536,t=2,p=1"), std::string::npos) << "INTERACTIVE limits expected: " << hash;
  // Neither the database nor its write-ahead log holds the password itself.
  for (const char* suffix : {"", "-wal"}) {
    const auto bytes = file_bytes(database().string() + suffix);
    EXPECT_EQ(bytes.find(password), std::string::npos) << "plaintext password in swarmdesign.db" << suffix;
  }
}

TEST_F(workflow_accounts, SignInWritesAPrivateTokenWhoseHashAloneIsStored) {
  sign_up("alice", "correct horse battery");
  const std::string out = run_ok({"sign-in", "alice", "--password-stdin"}, "correct horse battery\n");
  EXPECT_NE(out.find("Signed in as alice"), std::string::npos);

  struct stat status {};
  ASSERT_EQ(::stat((home() / "session").c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0600u);
  struct stat database_status {};
  ASSERT_EQ(::stat(database().c_str(), &database_status), 0);
  EXPECT_EQ(database_status.st_mode & 07777, 0600u) << "the database holds password hashes";

  std::string token = file_bytes(home() / "session");
  ASSERT_EQ(token.size(), 65u);  // 64 hex digits and a newline
  token.pop_back();
  EXPECT_EQ(query("SELECT count(*) FROM sessions"), "1");
  EXPECT_EQ(query("SELECT length(token_hash) FROM sessions"), "32");
  EXPECT_EQ(query("SELECT count(*) FROM sessions WHERE hex(token_hash) = upper('" + token + "') OR token_hash = '" +
                  token + "'"),
            "0");
  EXPECT_EQ(file_bytes(database()).find(token), std::string::npos);
  EXPECT_EQ(file_bytes(database().string() + "-wal").find(token), std::string::npos);

  const auto lifetime = std::stoll(query("SELECT expires_at - created_at FROM sessions"));
  EXPECT_EQ(lifetime, 7 * 24 * 3600);
}

TEST_F(workflow_accounts, FiveWrongPasswordsLockTheNameKnownOrNotUntilTheLockOutEnds) {
  sign_up("alice", "correct horse battery");
  for (const std::string name : {"alice", "nobody"}) {
    for (int i = 0; i < 5; ++i)
      expect_error(run({"sign-in", name, "--password-stdin"}, "wrong password\n"), 1, "wrong user name or password");
    // Locked: even the right password waits, and the words tell no name apart.
    expect_error(run({"sign-in", name, "--password-stdin"}, "correct horse battery\n"), 1,
                 "too many failed sign-ins for '" + name + "': try again in ");
  }
  EXPECT_FALSE(std::filesystem::exists(home() / "session"));
  // The lock-out over (its end moved to the past rather than waiting a minute), the right
  // password works again and starts the count anew.
  storage::Database(database(), false).execute("UPDATE sign_in_failures SET locked_until = 1");
  EXPECT_NE(run_ok({"sign-in", "alice", "--password-stdin"}, "correct horse battery\n").find("Signed in as alice"),
            std::string::npos);
  EXPECT_EQ(query("SELECT count(*) FROM sign_in_failures WHERE name = 'alice'"), "0");
}

TEST_F(workflow_accounts, SigningInAgainReplacesTheSession) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  EXPECT_EQ(query("SELECT count(*) FROM sessions"), "1");
}

TEST_F(workflow_accounts, ExitEndsTheSessionEverywhere) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  EXPECT_NE(run_ok({"exit"}).find("Signed out alice"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(home() / "session"));
  EXPECT_EQ(query("SELECT count(*) FROM sessions"), "0");
  expect_error(run({"show-projects"}), 1, "not signed in");
  // Signing out twice is harmless.
  EXPECT_NE(run_ok({"exit"}).find("Not signed in"), std::string::npos);
}

TEST_F(workflow_accounts, AnExpiredSessionIsRefused) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  {
    storage::Database db(database(), false);
    db.execute("UPDATE sessions SET created_at = created_at - 700000, expires_at = " +
               std::to_string(storage::unix_now() - 1));
  }
  expect_error(run({"show-projects"}), 1, "expired");
  sign_in("alice", "correct horse battery");  // and a new sign-in clears it away
  EXPECT_EQ(query("SELECT count(*) FROM sessions"), "1");
  run_ok({"show-projects"});
}

TEST_F(workflow_accounts, ASessionFileOthersCanReadIsRefused) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  std::filesystem::permissions(home() / "session", std::filesystem::perms::group_read | std::filesystem::perms::others_read,
                               std::filesystem::perm_options::add);
  expect_error(run({"show-projects"}), 1, "not private to you");
}

TEST_F(workflow_accounts, ShowUsersListsEveryAccountAndMarksTheSignedInOne) {
  sign_up("alice", "correct horse battery");
  sign_up("bob", "another good password");
  sign_in("bob", "another good password");
  const auto users = nlohmann::json::parse(run_ok({"show-users", "--json"}))["users"];
  ASSERT_EQ(users.size(), 2u);
  EXPECT_EQ(users[0]["name"], "alice");
  EXPECT_EQ(users[0]["signed_in"], false);
  EXPECT_EQ(users[1]["name"], "bob");
  EXPECT_EQ(users[1]["signed_in"], true);
  EXPECT_NE(run_ok({"showUsers"}).find("* bob"), std::string::npos);
}

TEST_F(workflow_accounts, DefaultHomeIsUnderXdgDataHomeThenUnderHome) {
  const auto xdg = scratch() / "xdg";
  run_swarmdesign({"sign-up", "alice", "--password-stdin"}, "correct horse battery\n",
                  Environment{{{"XDG_DATA_HOME", xdg.string()}, {"HOME", (scratch() / "h").string()}},
                              {"SWARMDESIGN_HOME"}});
  EXPECT_TRUE(std::filesystem::exists(xdg / "swarmdesign" / "swarmdesign.db"));

  run_swarmdesign({"show-users"}, "", Environment{{{"HOME", (scratch() / "h").string()}}, {"SWARMDESIGN_HOME", "XDG_DATA_HOME"}});
  EXPECT_TRUE(std::filesystem::exists(scratch() / "h" / ".local" / "share" / "swarmdesign" / "swarmdesign.db"));
}

TEST_F(workflow_accounts, EveryCommandHasHelpWithAnExample) {
  for (const char* command : {"sign-up", "signUp", "sign-in", "signIn", "exit", "show-users", "showUsers", "new-project",
                              "newProject", "show-projects", "showProjects", "select-project", "selectProject",
                              "active-project", "activeProject", "set-budget", "setBudget", "set-mission", "setMission"}) {
    const Outcome outcome = run({command, "--help"});
    EXPECT_EQ(outcome.exit_code, 0) << command;
    EXPECT_NE(outcome.out.find("Example:\n  swarmdesign "), std::string::npos) << command << ":\n" << outcome.out;
  }
  EXPECT_NE(run({"sign-in", "--help"}).out.find("A session lasts 7 days"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(home())) << "--help must not create any state";
}

}  // namespace
}  // namespace sd::test
