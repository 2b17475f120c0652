// Projects and the design settings, end to end, and the isolation between users.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "workflow/workflow_fixture.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

using workflow_projects = WorkflowTest;

TEST_F(workflow_projects, FromSignUpToAProjectReadyToDesign) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  EXPECT_NE(run_ok({"new-project", "aggregation"}).find("Created local project aggregation"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_directory(home() / "users" / "alice" / "projects" / "aggregation"));
  EXPECT_NE(run_ok({"select-project", "aggregation"}).find("Active project: aggregation"), std::string::npos);
  EXPECT_NE(run_ok({"active-project"}).find("Active project: aggregation"), std::string::npos);
  EXPECT_NE(run_ok({"set-budget", "200000"}).find("200000 simulation runs"), std::string::npos);
  EXPECT_NE(run_ok({"set-mission", "aac"}).find("Mission of aggregation: aac"), std::string::npos);

  const auto project = nlohmann::json::parse(run_ok({"active-project", "--json"}));
  EXPECT_EQ(project["name"], "aggregation");
  EXPECT_EQ(project["location"], "local");
  EXPECT_EQ(project["mission"], "aac");
  EXPECT_EQ(project["budget"], 200000);
  EXPECT_EQ(project["active"], true);
  EXPECT_EQ(project["folder"], (home() / "users" / "alice" / "projects" / "aggregation").string());
  // The folder is stored relative to the home, so a home can be moved as a whole.
  EXPECT_EQ(query("SELECT path FROM projects"), "users/alice/projects/aggregation");
}

TEST_F(workflow_projects, SetMissionWithoutANameOffersANumberedList) {
  user_with_active_project("alice", "p");
  const std::string by_number = run_ok({"set-mission"}, "1\n");
  EXPECT_NE(by_number.find("   1. aac"), std::string::npos) << by_number;
  EXPECT_NE(by_number.find("Mission (number or name): "), std::string::npos);
  EXPECT_EQ(query("SELECT mission FROM projects"), "aac");

  // A user's own mission in $SWARMDESIGN_HOME/missions is offered by name too.
  std::ifstream in(std::string(::sd::test::source_dir()) + "/missions/aac.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string mission = text.str();
  mission.replace(mission.find("\"name\": \"aac\""), 13, "\"name\": \"my-aac\"");
  std::filesystem::create_directories(home() / "missions");
  std::ofstream(home() / "missions" / "my-aac.json") << mission;
  run_ok({"set-mission"}, "my-aac\n");
  EXPECT_EQ(query("SELECT mission FROM projects"), "my-aac");
}

TEST_F(workflow_projects, TheThesisSpellingsWork) {
  run_ok({"signUp", "alice", "--password-stdin"}, "correct horse battery\n");
  run_ok({"signIn", "alice", "--password-stdin"}, "correct horse battery\n");
  run_ok({"newProject", "p"});
  run_ok({"selectProject", "p"});
  run_ok({"setBudget", "1000"});
  run_ok({"setMission", "aac"});
  EXPECT_NE(run_ok({"activeProject"}).find("1000 simulation runs"), std::string::npos);
  EXPECT_NE(run_ok({"showProjects"}).find("* p"), std::string::npos);
}

TEST_F(workflow_projects, TwoUsersNeverSeeEachOthersProjects) {
  user_with_active_project("alice", "secret-study");
  run_ok({"set-budget", "5000"});
  const std::string alice_view = run_ok({"show-projects", "--json"});

  sign_up("bob", "another good password");
  sign_in("bob", "another good password");
  EXPECT_TRUE(nlohmann::json::parse(run_ok({"show-projects", "--json"}))["projects"].empty());
  expect_error(run({"active-project"}), 1, "no active project");

  // Bob's attempts on Alice's project read exactly like attempts on a project that does not exist.
  const Outcome foreign = run({"select-project", "secret-study"});
  const Outcome missing = run({"select-project", "no-such-one"});
  expect_error(foreign, 1, "no project named 'secret-study'");
  EXPECT_EQ(foreign.err.substr(0, foreign.err.find('\'')), missing.err.substr(0, missing.err.find('\'')));
  EXPECT_EQ(foreign.err.substr(foreign.err.rfind('\'')), missing.err.substr(missing.err.rfind('\'')));

  // The same name is free for Bob, in his own workspace.
  run_ok({"new-project", "secret-study"});
  run_ok({"select-project", "secret-study"});
  run_ok({"set-budget", "7"});
  EXPECT_TRUE(std::filesystem::is_directory(home() / "users" / "bob" / "projects" / "secret-study"));

  sign_in("alice", "alice-secret-pw");
  EXPECT_EQ(run_ok({"show-projects", "--json"}), alice_view);
  EXPECT_EQ(nlohmann::json::parse(run_ok({"active-project", "--json"}))["budget"], 5000);
}

TEST_F(workflow_projects, AClusterProjectIsRecordedWithWhereItsJobsRun) {
  sign_up("alice", "correct horse battery");
  sign_in("alice", "correct horse battery");
  const std::string out = run_ok({"new-project", "big", "--cluster", "hpc.example.org", "--cluster-user", "al"});
  EXPECT_NE(out.find("job folders in ~/swarmdesign"), std::string::npos) << out;
  EXPECT_NE(out.find("swarmdesign cluster-check"), std::string::npos) << out;
  EXPECT_EQ(query("SELECT host || ' ' || user_name FROM cluster_connections"), "hpc.example.org al");
  EXPECT_EQ(query("SELECT location FROM projects"), "cluster");

  run_ok({"select-project", "big"});
  EXPECT_NE(run_ok({"active-project"}).find("cluster: al@hpc.example.org"), std::string::npos);
  const auto project = nlohmann::json::parse(run_ok({"active-project", "--json"}));
  EXPECT_EQ(project["cluster"]["host"], "hpc.example.org");
  EXPECT_EQ(project["cluster"]["user"], "al");
  EXPECT_EQ(project["cluster"]["binary"], "swarmdesign");

  // Where its jobs go and which program runs them can change; a path that would break out of
  // a job script's quoting is refused before anything is written.
  run_ok({"set-cluster", "--cluster-dir", "/scratch/al", "--cluster-binary", "~/bin/swarmdesign"});
  const auto changed = nlohmann::json::parse(run_ok({"active-project", "--json"}));
  EXPECT_EQ(changed["cluster"]["folder"], "/scratch/al");
  EXPECT_EQ(changed["cluster"]["binary"], "~/bin/swarmdesign");
  const std::string before = snapshot();
  expect_error(run({"set-cluster", "--cluster-dir", "/x'; rm -rf ~; '"}), 2, "cluster folder");
  expect_error(run({"new-project", "b3", "--cluster", "h", "--cluster-user", "al", "--cluster-binary", "$(boom)"}), 2,
               "cluster binary");
  EXPECT_EQ(snapshot(), before);

  // A second project on the same cluster reuses the connection.
  run_ok({"new-project", "big2", "--cluster", "hpc.example.org", "--cluster-user", "al"});
  EXPECT_EQ(query("SELECT count(*) FROM cluster_connections"), "1");
}

}  // namespace
}  // namespace sd::test
