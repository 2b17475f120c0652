// Quotas on a lab's server (issue #56): an administrator sets a server default and an account's
// own limits, from the CLI and the page; a user sees theirs; work past a limit is refused in
// one line before anything is written, and a start that is refused, fails or only resumes
// counts no runs (and, refused, writes nothing: the bad-input catalogue checks every byte).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/served_workflow.hpp"

namespace sd::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class quotas : public ServedWorkflowTest {
 protected:
  void SetUp() override {
    ServedWorkflowTest::SetUp();
    user_with_active_project("boss", "lab");  // the home's first account: its administrator
    mission_ = write_short_mission(home() / "users" / "boss" / "projects" / "lab", 2);
    run_ok({"set-mission", mission_.string()});
    run_ok({"set-budget", "1400"});
    sign_up("ann", "ann-secret-pw");
    sign_in("ann", "ann-secret-pw");
    run_ok({"new-project", "ann-work"});
    run_ok({"select-project", "ann-work"});
    sign_in("boss", "boss-secret-pw");
  }
  json my_quota() { return json::parse(run_ok({"quota", "--json"})); }
  std::string mission_text() const {
    std::ifstream in(mission_);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::path mission_;
};

TEST_F(quotas, AnAdministratorSetsTheDefaultAndAnAccountsOwnFromTheCliAndThePageAndTheUserSeesThem) {
  run_ok({"admin", "quota", "--default", "--disk", "5MB", "--runs-per-day", "4000"});
  run_ok({"admin", "quota", "ann", "--runs-per-day", "100000"});
  sign_in("ann", "ann-secret-pw");
  const json ann = my_quota();
  EXPECT_EQ(ann["disk_limit"], 5000000);
  EXPECT_EQ(ann["disk_from_default"], true);
  EXPECT_EQ(ann["runs_per_day"], 100000);
  EXPECT_EQ(ann["runs_from_default"], false);
  EXPECT_EQ(ann["runs_today"], 0);
  EXPECT_NE(run_ok({"quota"}).find("ann: disk 0 B of 5.0 MB (server default); runs today (UTC) 0 of 100000 (own)"),
            std::string::npos);
  WebClient ann_page = signed_in("ann", "ann-secret-pw");
  EXPECT_EQ(ann_page.get("/api/quota").body, ann);

  // A plain user changes no quota, from either front end.
  expect_error(run({"admin", "quota", "ann", "--runs-per-day", "none"}), 1, "only an administrator");
  EXPECT_EQ(ann_page.post("/api/admin/quota", {{"disk_limit", nullptr}, {"runs_per_day", nullptr}}).status, 403);
  EXPECT_EQ(ann_page.post("/api/admin/users/ann/quota", {{"disk_limit", nullptr}, {"runs_per_day", nullptr}}).status, 403);
  EXPECT_EQ(ann_page.get("/api/admin/quota").status, 403);

  // The administrator's page: the default, an account's own (none, default), the listing.
  WebClient boss = signed_in("boss", "boss-secret-pw");
  EXPECT_EQ(boss.get("/api/admin/quota").body, (json{{"disk_limit", 5000000}, {"runs_per_day", 4000}}));
  const Answer set = boss.post("/api/admin/users/ann/quota", {{"disk_limit", nullptr}, {"runs_per_day", "default"}});
  ASSERT_EQ(set.status, 200) << set.text;
  EXPECT_TRUE(set.body["quota"]["disk_limit"].is_null());
  EXPECT_EQ(set.body["quota"]["disk_from_default"], false);
  EXPECT_EQ(set.body["quota"]["runs_per_day"], 4000);
  EXPECT_EQ(set.body["quota"]["runs_from_default"], true);
  EXPECT_EQ(ann_page.get("/api/quota").body["runs_per_day"], 4000);
  const Answer listing = boss.get("/api/admin/users");
  ASSERT_EQ(listing.body[0]["name"], "ann");
  EXPECT_EQ(listing.body[0]["quota"], set.body["quota"]);
  const Answer server = boss.post("/api/admin/quota", {{"disk_limit", 1000000}, {"runs_per_day", nullptr}});
  EXPECT_EQ(server.body, (json{{"disk_limit", 1000000}, {"runs_per_day", nullptr}}));
  sign_in("boss", "boss-secret-pw");
  EXPECT_NE(run_ok({"admin", "quota", "--default"}).find("Server default: disk 1.0 MB; runs per day no limit"), std::string::npos);

  // Bad input: one line, nothing changed.
  expect_error(run({"admin", "quota", "ann", "--disk", "5 parsecs"}), 2, "disk quota '5 parsecs': a size such as 500MB");
  expect_error(run({"admin", "quota", "ann", "--runs-per-day", "-3"}), 2, "runs per day '-3': a whole number");
  expect_error(run({"admin", "quota", "--disk", "1GB"}), 2, "name an account or give --default");
  expect_error(run({"admin", "quota", "nobody", "--disk", "1GB"}), 1, "no account named 'nobody'");
  EXPECT_EQ(boss.post("/api/admin/quota", {{"disk_limit", -3}, {"runs_per_day", nullptr}}).status, 400);
  EXPECT_EQ(boss.post("/api/admin/quota", {{"disk_limit", "lots"}, {"runs_per_day", nullptr}}).status, 400);
  EXPECT_EQ(boss.post("/api/admin/users/ann/quota", {{"runs_per_day", 5}}).status, 400) << "disk_limit missing";
  EXPECT_EQ(boss.get("/api/admin/quota").body["disk_limit"], 1000000);
  EXPECT_EQ(query("SELECT quota_runs_per_day IS NULL FROM users WHERE name = 'ann'"), "1");
}

TEST_F(quotas, ADesignPastTheRunsQuotaIsRefusedWhileAResumedOneGoesOnAndARefusedStartCostsNothing) {
  run_ok({"admin", "quota", "boss", "--runs-per-day", "2000"});
  kill_at_checkpoint(3);
  EXPECT_EQ(run({"run-design", "--threads", "2"}).exit_code, -1) << "killed after it started";
  kill_at_checkpoint(0);
  EXPECT_EQ(my_quota()["runs_today"], 1400) << "its budget, counted when it started";

  // 600 runs left: the interrupted design resumes all the same, counting nothing more.
  run_ok({"run-design", "--threads", "2"});
  EXPECT_EQ(query("SELECT state FROM designs"), "finished");
  EXPECT_EQ(my_quota()["runs_today"], 1400);

  const std::string before = snapshot();
  expect_error(run({"run-design", "--new"}), 1,
               "runs quota: this design needs 1400 runs, and boss has 600 of 2000 runs left today (UTC)");
  EXPECT_EQ(snapshot(), before) << "a refused start writes nothing";
  // Refused for another reason after the quota passed it: it counts nothing.
  run_ok({"set-budget", "500"});
  expect_error(run({"run-design", "--new"}), 2, "below the minimum");
  EXPECT_EQ(my_quota()["runs_today"], 1400);
  // An experiment counts its whole plan.
  expect_error(run({"experiment", "combination", "--missions", "aac", "--designs", "1"}), 1, "runs quota: this experiment needs");
  EXPECT_EQ(query("SELECT count(*) FROM experiments"), "0");
}

TEST_F(quotas, AFileOrADesignPastTheDiskQuotaIsRefusedInOneLineAndNothingIsWritten) {
  const fs::path ann_folder = home() / "users" / "ann" / "projects" / "ann-work";
  const std::string text = mission_text();
  run_ok({"admin", "quota", "ann", "--disk", std::to_string(text.size() / 2)});
  WebClient ann = signed_in("ann", "ann-secret-pw");
  const Answer refused = ann.post("/api/projects/ann-work/missions", {{"name", "mine"}, {"text", text}});
  EXPECT_EQ(refused.status, 409);
  EXPECT_EQ(refused.body["quota"], "disk") << "which quota, for scripts";
  EXPECT_NE(refused.body["error"].get<std::string>().find("disk quota: this needs"), std::string::npos) << refused.text;
  EXPECT_EQ(refused.body["error"].get<std::string>().find(home().string()), std::string::npos) << "no server path";
  EXPECT_FALSE(fs::exists(ann_folder / "missions" / "mine.json"));
  const Answer software = ann.post("/api/projects/ann-work/software", {{"name", "s"}, {"text", "--fsm-config --nstates 1 --s0 1"}});
  EXPECT_EQ(software.status, 200) << "a few bytes still fit: " << software.text;

  // Room made: the same mission is saved; its replacement by itself does not grow the account.
  run_ok({"admin", "quota", "ann", "--disk", std::to_string(text.size() + 4096)});
  ASSERT_EQ(ann.post("/api/projects/ann-work/missions", {{"name", "mine"}, {"text", text}}).status, 200);
  run_ok({"admin", "quota", "ann", "--disk", "1000"});
  EXPECT_EQ(ann.post("/api/projects/ann-work/missions", {{"name", "mine"}, {"text", text}}).status, 200)
      << "the same bytes again, over a lowered limit";

  // Over its limit, no design starts, from the page or the CLI.
  const Answer design = ann.post("/api/projects/ann-work/designs", json::object());
  EXPECT_EQ(design.status, 409);
  EXPECT_EQ(design.body["quota"], "disk");
  EXPECT_NE(design.body["error"].get<std::string>().find("disk quota: ann uses"), std::string::npos) << design.text;
  sign_in("ann", "ann-secret-pw");
  run_ok({"set-mission", (ann_folder / "missions" / "mine.json").string()});
  run_ok({"set-budget", "1400"});
  expect_error(run({"run-design"}), 1, "disk quota: ann uses");
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
  EXPECT_EQ(my_quota()["runs_today"], 0);
}

}  // namespace
}  // namespace sd::test
