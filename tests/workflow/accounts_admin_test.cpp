// A lab's server administered (issue #56): the first account administers it; an administrator
// lists accounts with their use, disables, enables, resets a password, changes roles and
// deletes an account with everything it owns, from the CLI and from the web API alike; a user
// changes their own password. Tried as an attacker would: a plain user gets 403 everywhere,
// a disabled account opens no session, nothing of another account is touched.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/served_workflow.hpp"

namespace sd::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class accounts_admin : public ServedWorkflowTest {
 protected:
  void SetUp() override {
    ServedWorkflowTest::SetUp();
    user_with_active_project("boss", "lab");  // the home's first account: its administrator
    sign_up("ann", "ann-secret-pw");
    sign_up("bob", "bob-secret-pw");
    sign_in("ann", "ann-secret-pw");
    run_ok({"new-project", "ann-work"});
    write_short_mission(home() / "users" / "ann" / "projects" / "ann-work", 2);
    sign_in("boss", "boss-secret-pw");
    serve();
  }
};

TEST_F(accounts_admin, TheFirstAccountAdministersAndSeesEveryAccountsUse) {
  const json cli = json::parse(run_ok({"admin", "users", "--json"}));
  ASSERT_EQ(cli.size(), 3u);
  EXPECT_EQ(cli[0]["name"], "ann");
  EXPECT_EQ(cli[0]["role"], "user");
  EXPECT_GT(cli[0]["disk_bytes"].get<std::uint64_t>(), 0u) << "ann's mission file";
  EXPECT_EQ(cli[2]["name"], "boss");
  EXPECT_EQ(cli[2]["role"], "admin");
  EXPECT_FALSE(cli[2]["last_sign_in"].is_null());
  WebClient boss = signed_in("boss", "boss-secret-pw");
  EXPECT_EQ(boss.get("/api/session").body["admin"], true);
  const Answer page = boss.get("/api/admin/users");
  ASSERT_EQ(page.status, 200) << page.text;
  ASSERT_EQ(page.body.size(), 3u);
  EXPECT_EQ(page.body[0]["disk_bytes"], cli[0]["disk_bytes"]);
  EXPECT_NE(run_ok({"admin", "users"}).find("boss                 admin"), std::string::npos);
}

TEST_F(accounts_admin, APlainUserIsRefusedEveryAdministrationFromTheCliAndThePage) {
  sign_in("ann", "ann-secret-pw");
  expect_error(run({"admin", "users"}), 1, "only an administrator");
  expect_error(run({"admin", "disable", "bob"}), 1, "only an administrator");
  expect_error(run({"admin", "reset-password", "boss"}), 1, "only an administrator");
  expect_error(run({"admin", "delete-user", "bob", "--yes"}), 1, "only an administrator");
  WebClient ann = signed_in("ann", "ann-secret-pw");
  EXPECT_EQ(ann.get("/api/session").body["admin"], false);
  EXPECT_EQ(ann.get("/api/admin/users").status, 403);
  for (const char* verb : {"disable", "enable", "reset-password", "delete"})
    EXPECT_EQ(ann.post(std::string("/api/admin/users/bob/") + verb, {{"confirm", "bob"}}).status, 403) << verb;
  EXPECT_EQ(ann.post("/api/admin/users/ann/role", {{"role", "admin"}}).status, 403);
  // Without the session's CSRF token even an administrator's page is refused.
  WebClient boss = signed_in("boss", "boss-secret-pw");
  EXPECT_EQ(boss.post("/api/admin/users/bob/disable", json::object(), false).status, 403);
  EXPECT_EQ(query("SELECT disabled FROM users WHERE name = 'bob'"), "0");
  EXPECT_EQ(query("SELECT role FROM users WHERE name = 'ann'"), "user");
}

TEST_F(accounts_admin, ADisabledAccountOpensNoSessionAndItsOpenOnesEnd) {
  WebClient bob = signed_in("bob", "bob-secret-pw");
  ASSERT_EQ(bob.get("/api/projects").status, 200);
  WebClient boss = signed_in("boss", "boss-secret-pw");
  ASSERT_EQ(boss.post("/api/admin/users/bob/disable", json::object()).status, 200);
  EXPECT_EQ(bob.get("/api/projects").status, 401) << "the open session ended";
  WebClient again(port());
  EXPECT_FALSE(again.sign_in("bob", "bob-secret-pw"));
  EXPECT_NE(again.last_refusal().find("disabled"), std::string::npos) << again.last_refusal();
  WebClient guess(port());
  EXPECT_FALSE(guess.sign_in("bob", "not-his-password"));
  EXPECT_EQ(guess.last_refusal().find("disabled"), std::string::npos) << "a wrong password learns nothing";
  expect_error(run({"sign-in", "bob", "--password-stdin"}, "bob-secret-pw\n"), 1, "disabled");
  expect_error(run({"admin", "disable", "boss"}), 2, "your own account");
  run_ok({"admin", "enable", "bob"});
  EXPECT_TRUE(WebClient(port()).sign_in("bob", "bob-secret-pw"));
}

TEST_F(accounts_admin, ANewPasswordIsShownOnceAndEndsTheAccountsSessions) {
  WebClient ann = signed_in("ann", "ann-secret-pw");
  WebClient boss = signed_in("boss", "boss-secret-pw");
  const Answer reset = boss.post("/api/admin/users/ann/reset-password", json::object());
  ASSERT_EQ(reset.status, 200) << reset.text;
  const std::string password = reset.body["password"];
  EXPECT_EQ(password.size(), 20u);
  EXPECT_EQ(ann.get("/api/projects").status, 401);
  EXPECT_FALSE(WebClient(port()).sign_in("ann", "ann-secret-pw"));
  WebClient fresh = signed_in("ann", password);
  // Ann changes it on the page: her other sessions end, this one stays.
  WebClient other = signed_in("ann", password);
  EXPECT_EQ(fresh.post("/api/password", {{"current", "wrong-one-here"}, {"new", "ann-new-secret"}}).status, 403);
  EXPECT_EQ(fresh.post("/api/password", {{"current", password}, {"new", "short"}}).status, 400);
  ASSERT_EQ(fresh.post("/api/password", {{"current", password}, {"new", "ann-new-secret"}}).status, 200);
  EXPECT_EQ(fresh.get("/api/projects").status, 200);
  EXPECT_EQ(other.get("/api/projects").status, 401);
  // And from the CLI: the terminal stays signed in.
  sign_in("ann", "ann-new-secret");
  run_ok({"change-password", "--password-stdin"}, "ann-new-secret\nann-third-secret\n");
  EXPECT_NE(run_ok({"show-projects"}).find("ann-work"), std::string::npos);
  EXPECT_EQ(fresh.get("/api/projects").status, 401);
  expect_error(run({"change-password", "--password-stdin"}, "not-the-password\nann-fourth-secret\n"), 1, "current password is wrong");
}

TEST_F(accounts_admin, DeletingAnAccountTakesEverythingItOwnedAndNothingElse) {
  const fs::path ann_folder = home() / "users" / "ann";
  const fs::path boss_project = home() / "users" / "boss" / "projects" / "lab";
  ASSERT_TRUE(fs::exists(ann_folder));
  expect_error(run({"admin", "delete-user", "ann"}), 2, "--yes");
  WebClient boss = signed_in("boss", "boss-secret-pw");
  EXPECT_EQ(boss.post("/api/admin/users/ann/delete", {{"confirm", "bob"}}).status, 400);
  EXPECT_TRUE(fs::exists(ann_folder));
  ASSERT_EQ(boss.post("/api/admin/users/ann/delete", {{"confirm", "ann"}}).status, 200);
  EXPECT_FALSE(fs::exists(ann_folder));
  EXPECT_TRUE(fs::exists(boss_project));
  EXPECT_EQ(query("SELECT count(*) FROM users"), "2");
  EXPECT_EQ(query("SELECT count(*) FROM projects WHERE name = 'ann-work'"), "0");
  EXPECT_EQ(boss.post("/api/admin/users/ann/delete", {{"confirm", "ann"}}).status, 404);
  run_ok({"admin", "role", "bob", "admin"});
  EXPECT_EQ(query("SELECT role FROM users WHERE name = 'bob'"), "admin");
  run_ok({"admin", "delete-user", "bob", "--yes"});
  EXPECT_EQ(query("SELECT count(*) FROM users"), "1");
  expect_error(run({"admin", "delete-user", "boss", "--yes"}), 2, "your own account");
}

}  // namespace
}  // namespace sd::test
