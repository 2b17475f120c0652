// A project's mission set from the page and from the CLI through one service (issue #56):
// `set-mission` and POST /api/projects/NAME/mission accept the same missions, refuse the same
// ones in the same line (an unknown name, a malformed file, a running design) and change
// nothing then, not even the active project; the page cannot name another account's file.
// Deleting a project whose mission file other projects use names them beforehand
// (`mission_used_by`), and they then say "its mission file was deleted" instead of failing as
// a file that is not the user's, until another mission is chosen.
#include <gtest/gtest.h>

#include <chrono>
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
using namespace std::chrono_literals;

class project_mission : public ServedWorkflowTest {
 protected:
  void SetUp() override {
    ServedWorkflowTest::SetUp();
    user_with_active_project("ann", "holder");
    run_ok({"set-mission", "aac"});
    run_ok({"set-budget", "1400"});
    run_ok({"new-project", "user"});
    run_ok({"select-project", "user"});
    run_ok({"set-mission", "aac"});
    run_ok({"set-budget", "1400"});
    sign_up("bob", "bob-secret-pw");
    sign_in("bob", "bob-secret-pw");
    run_ok({"new-project", "bobs"});
    run_ok({"select-project", "bobs"});
    run_ok({"set-mission", "aac"});
    sign_in("ann", "ann-secret-pw");
    serve();
    ann_.emplace(signed_in("ann", "ann-secret-pw"));
    // Ann's own mission, uploaded into "holder" as the page does.
    const fs::path draft = write_short_mission(scratch());
    std::ifstream in(draft);
    const Answer saved = ann_->post("/api/projects/holder/missions",
                                    {{"name", "corner"}, {"text", std::string(std::istreambuf_iterator<char>(in), {})}});
    EXPECT_EQ(saved.status, 200) << saved.text;
    file_ = saved.body["name"].get<std::string>();
  }
  void TearDown() override {
    ann_.reset();
    ServedWorkflowTest::TearDown();
  }
  Answer set_from_page(WebClient& client, const std::string& project, const json& mission) {
    return client.post("/api/projects/" + project + "/mission", {{"mission", mission}});
  }
  json project_doc(const std::string& name) {
    for (const json& p : ann_->get("/api/projects").body)
      if (p["name"] == name) return p;
    ADD_FAILURE() << "no project " << name;
    return {};
  }
  /// The page's refusal: its status and its one line, with nothing changed.
  void expect_page_refusal(const Answer& answer, int status, const std::string& part) {
    EXPECT_EQ(answer.status, status) << answer.text;
    const std::string error = answer.body.value("error", "");
    EXPECT_NE(error.find(part), std::string::npos) << "expected '" << part << "' in: " << answer.text;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  }

  std::optional<WebClient> ann_;
  std::string file_;  // ann's uploaded mission, as /api/missions names it
};

TEST_F(project_mission, ThePageAndTheCliSetAMissionThroughOneServiceWithTheSameRefusals) {
  // From the page: a mission file of her own projects, the project made active as the CLI's.
  const Answer set = set_from_page(*ann_, "holder", file_);
  ASSERT_EQ(set.status, 200) << set.text;
  EXPECT_EQ(set.body["mission"], file_);
  EXPECT_EQ(set.body["active"], true);
  EXPECT_TRUE(set.body["mission_problem"].is_null());
  const json active = json::parse(run_ok({"active-project", "--json"}));
  EXPECT_EQ(active["name"], "holder");
  EXPECT_EQ(active, set.body) << "the CLI's document is the page's";
  // And back to a catalogue name from the CLI, on the project the page made active.
  EXPECT_NE(run_ok({"set-mission", "aac"}).find("Mission of holder: aac."), std::string::npos);
  EXPECT_EQ(set_from_page(*ann_, "user", "aac").body["mission"], "aac");
  run_ok({"select-project", "holder"});

  // Refused alike, in one line, and nothing changes: not the mission, not the active project.
  const fs::path broken = home() / "users" / "ann" / "projects" / "holder" / "broken.json";
  std::ofstream(broken) << R"({"name": "broken", "robots": 0})";
  const std::string before = snapshot();
  expect_error(run({"set-mission", "no-such-mission"}), 2, "unknown mission 'no-such-mission'");
  expect_page_refusal(set_from_page(*ann_, "user", "no-such-mission"), 400, "unknown mission 'no-such-mission'");
  const Outcome cli_broken = run({"set-mission", broken.string()});
  expect_error(cli_broken, 2, "broken.json");
  const Answer page_broken = set_from_page(*ann_, "user", broken.string());
  expect_page_refusal(page_broken, 400, "broken.json");
  EXPECT_NE(cli_broken.err.find(page_broken.body["error"].get<std::string>()), std::string::npos)
      << "the CLI's line is the page's (plus the CLI's hint)\n" << cli_broken.err << page_broken.text;
  expect_page_refusal(set_from_page(*ann_, "user", ""), 400, "no mission chosen");
  expect_page_refusal(ann_->post("/api/projects/user/mission", json::object()), 400, "mission is missing");
  expect_page_refusal(set_from_page(*ann_, "user", 7.5), 400, "mission must be text");
  expect_page_refusal(set_from_page(*ann_, "nothing-here", "aac"), 404, "nothing-here");
  // The server's rule for files: nothing outside her projects, whether it exists or not.
  const Answer system = set_from_page(*ann_, "user", "/etc/passwd");
  const Answer missing = set_from_page(*ann_, "user", (home() / "users" / "ann" / "projects" / "gone.json").string());
  EXPECT_EQ(system.status, 404);
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(snapshot(), before) << "a refused mission changes nothing";
  EXPECT_EQ(json::parse(run_ok({"active-project", "--json"}))["name"], "holder");
}

TEST_F(project_mission, ASecondAccountCannotSetTheFirstsMissionFileFromThePage) {
  WebClient bob = signed_in("bob", "bob-secret-pw");
  const std::string before = snapshot();
  const Answer theirs = set_from_page(bob, "bobs", file_);
  expect_page_refusal(theirs, 404, "is not a file of your projects");
  // The same words as for a file that does not exist: nothing learnt about ann's files.
  const std::string nowhere = fs::path(file_).replace_filename("nowhere.json").string();
  const Answer none = set_from_page(bob, "bobs", nowhere);
  EXPECT_EQ(none.status, 404);
  std::string said = theirs.body["error"];
  said.replace(said.find("corner.json"), 11, "nowhere.json");
  EXPECT_EQ(said, none.body["error"]);
  EXPECT_EQ(said.find(home().string()), std::string::npos) << "no server path";
  // Nor ann's project: it is not bob's to name.
  EXPECT_EQ(set_from_page(bob, "holder", "aac").status, 404);
  EXPECT_EQ(snapshot(), before);
  EXPECT_EQ(query("SELECT mission FROM projects WHERE name = 'bobs'"), "aac");
}

TEST_F(project_mission, AMissionIsNotChangedWhileADesignOfTheProjectRunsFromEitherFrontEnd) {
  // Runs long enough to be caught running: 120 simulated seconds each.
  const fs::path slow = write_short_mission(home() / "users" / "ann" / "projects" / "holder", 120);
  ASSERT_EQ(set_from_page(*ann_, "holder", slow.string()).status, 200);
  const Answer started =
      ann_->post("/api/projects/holder/designs", {{"architectures", "fsm"}, {"flavours", "chocolate"}, {"seed", "3"}});
  ASSERT_EQ(started.status, 200) << started.text;
  ASSERT_EQ(started.body["state"], "running");
  const std::string running_line = "design " + std::to_string(started.body["id"].get<int>()) +
                                   " of project holder is running; stop it before changing the project's mission";
  run_ok({"select-project", "user"});
  expect_page_refusal(set_from_page(*ann_, "holder", "aac"), 409, running_line);
  run_ok({"select-project", "holder"});
  expect_error(run({"set-mission", "aac"}), 1, running_line);
  EXPECT_EQ(query("SELECT mission FROM projects WHERE name = 'holder'"), slow.string());
  EXPECT_EQ(json::parse(run_ok({"active-project", "--json"}))["name"], "holder");
  // Another project's mission is free to change meanwhile.
  EXPECT_EQ(set_from_page(*ann_, "user", file_).status, 200);

  ASSERT_EQ(ann_->post("/api/projects/holder/designs/stop", json::object()).status, 200);
  ASSERT_TRUE(wait_until([&] { return ann_->get("/api/projects/holder/status").body["design"]["state"] != "running"; },
                         60s));
  const Answer changed = set_from_page(*ann_, "holder", "aac");
  EXPECT_EQ(changed.status, 200) << changed.text;
  EXPECT_EQ(query("SELECT mission FROM designs"), slow.string()) << "the stopped design keeps the mission it started with";
}

TEST_F(project_mission, DeletingAProjectNamesTheProjectsUsingItsMissionWhichThenSaySoAndTakeAnother) {
  ASSERT_EQ(set_from_page(*ann_, "user", file_).status, 200);
  run_ok({"new-project", "third"});
  run_ok({"select-project", "third"});
  run_ok({"set-mission", file_});
  run_ok({"set-budget", "1400"});
  // Asked before deleting: the page's list and the CLI's say who uses holder's files.
  EXPECT_EQ(project_doc("holder")["mission_used_by"], (json{"third", "user"}));
  EXPECT_EQ(project_doc("user")["mission_used_by"], json::array());
  EXPECT_EQ(json::parse(run_ok({"show-projects", "--json"}))["projects"], ann_->get("/api/projects").body);

  const Answer deleted = ann_->post("/api/projects/holder/delete", {{"confirm", "holder"}});
  ASSERT_EQ(deleted.status, 200) << deleted.text;
  EXPECT_EQ(project_doc("user")["mission_problem"], "its mission file was deleted");
  EXPECT_EQ(project_doc("user")["mission"], file_) << "what it named stays, to say which";
  EXPECT_EQ(ann_->get("/api/projects/user/status").body["mission_problem"], "its mission file was deleted");
  EXPECT_NE(run_ok({"active-project"}).find("its mission file was deleted; choose another with: swarmdesign set-mission"),
            std::string::npos);

  // A design is refused in the project's words, from the page and the CLI, recording nothing.
  const std::string before = snapshot();
  const std::string line = "project user: its mission file was deleted; choose another mission";
  const Answer page_start = ann_->post("/api/projects/user/designs", {{"architectures", "fsm"}, {"flavours", "chocolate"}});
  expect_page_refusal(page_start, 404, line);
  EXPECT_EQ(page_start.text.find("is not a file of your projects"), std::string::npos) << page_start.text;
  EXPECT_EQ(snapshot(), before);
  run_ok({"select-project", "user"});
  const std::string selected = snapshot();
  expect_error(run({"run-design", "--fsm", "--chocolate"}), 1, line);
  EXPECT_EQ(snapshot(), selected);
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");

  // Another mission, and the project designs again: a tiny design on a short mission.
  const fs::path short_mission = write_short_mission(home() / "users" / "ann" / "projects" / "user", 2);
  const Answer chosen = set_from_page(*ann_, "user", short_mission.string());
  ASSERT_EQ(chosen.status, 200) << chosen.text;
  EXPECT_TRUE(chosen.body["mission_problem"].is_null());
  EXPECT_TRUE(project_doc("third")["mission_problem"].is_string()) << "each project chooses for itself";
  const Answer started = ann_->post("/api/projects/user/designs", {{"architectures", "fsm"}, {"flavours", "chocolate"}});
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body["mission"], short_mission.string());
  ASSERT_TRUE(wait_until([&] { return ann_->get("/api/projects/user/status").body["design"]["state"] == "finished"; },
                         120s));
}

TEST_F(project_mission, TheCliSaysWhichProjectsTakeTheirMissionFromTheProjectItDeletes) {
  run_ok({"set-mission", file_});  // "user", the active project, on holder's file
  run_ok({"run-design", "--fsm", "--chocolate", "--seed", "1", "--threads", "2"});
  run_ok({"new-project", "spare"});
  EXPECT_EQ(run_ok({"delete-project", "spare", "--yes"}), "Deleted project spare.\n") << "none uses its files";
  EXPECT_EQ(run_ok({"delete-project", "holder", "--yes"}),
            "Deleted project holder.\nProject(s) user take their mission from it: each then needs another (set-mission).\n");
  EXPECT_NE(run_ok({"active-project"}).find("its mission file was deleted"), std::string::npos);
  // Its design's best cannot run on the deleted file: said so, from the CLI and the page alike.
  run_ok({"select-project", "user"});
  const std::string line = "design 1's mission file was deleted, so its best cannot run on it";
  expect_error(run({"test-design", "--design", "1"}), 1, line);
  expect_error(run({"export-argos", "--design", "1", "--out", (scratch() / "argos").string()}), 1, line);
  expect_page_refusal(ann_->post("/api/projects/user/test", {{"seeds", "1-3"}, {"design", 1}}), 404, line);
}

}  // namespace
}  // namespace sd::test
