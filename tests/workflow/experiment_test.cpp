// Experiments through the real binary: the issue's scaled-down protocol (two missions, budget
// scale 0.007, two designs per condition) killed once and resumed to the same report as an
// uninterrupted run; designs another experiment already made are reused; --dry-run; and
// protocols that must be refused before anything is stored.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

class experiment : public WorkflowTest {
 protected:
  json report(const std::string& name, const std::string& project, const std::filesystem::path& out) {
    run_ok({"report", name, "--project", project, "--out", out.string()});
    std::ifstream in(out / "report.json");
    return json::parse(in);
  }
  int csv_rows(const std::filesystem::path& file) {
    std::ifstream in(file);
    int rows = -1;  // the header
    for (std::string line; std::getline(in, line);) ++rows;
    return rows;
  }
  std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const auto path = scratch() / name;
    std::ofstream(path) << text;
    return path;
  }
};

/// The final designs and their assessments, which an interruption must not change.
json results(const json& report) {
  json r = json::array();
  for (const auto& d : report["designs"])
    r.push_back({d["mission"], d["condition"], d["replicate"], d["seed"], d["configuration"], d["design_score"],
                 d["runs_used"], d["scores"], d["convergence"]});
  return r;
}

TEST_F(experiment, ScaledDownProtocolKilledOnceResumesToTheSameResults) {
  user_with_active_project("alice", "killed");
  const std::vector<std::string> command = {"experiment", "combination", "--missions", "aac,foraging",
                                            "--budget-scale", "0.007", "--designs", "2", "--eval-seeds", "3",
                                            "--threads", "2"};
  // Killed at the 60th race step of the process: inside the experiment, not at its start.
  kill_at_checkpoint(60);
  const Outcome killed = run(command);
  EXPECT_EQ(killed.exit_code, -1) << killed.out << killed.err;
  const json interrupted = json::parse(run_ok({"status", "--json"}))["experiments"][0];
  EXPECT_EQ(interrupted["state"], "interrupted");
  EXPECT_EQ(interrupted["designs"], 8);
  EXPECT_LT(interrupted["designs_done"].get<int>(), 4);  // killed inside an aac design
  EXPECT_EQ(interrupted["current"]["stage"], "designing");

  kill_at_checkpoint(0);
  const std::string resumed = run_ok(command);
  EXPECT_NE(resumed.find("was interrupted; resuming it"), std::string::npos) << resumed;
  EXPECT_NE(resumed.find("Report it with: swarmdesign report combination"), std::string::npos);
  EXPECT_EQ(json::parse(run_ok({"status", "--json"}))["experiments"][0]["state"], "finished");

  // The designs up to the one that was killed, never interrupted, in another project (designs
  // after it ran in one process either way; their seeds do not depend on the missions kept).
  run_ok({"new-project", "straight"});
  run_ok({"select-project", "straight"});
  std::vector<std::string> aac_only = command;
  aac_only[3] = "aac";
  run_ok(aac_only);

  const json a = report("combination", "killed", scratch() / "killed-report");
  const json b = report("combination", "straight", scratch() / "straight-report");
  ASSERT_EQ(b["designs"].size(), 4u);
  json a_aac = a;
  a_aac["designs"].erase(a_aac["designs"].begin() + 4, a_aac["designs"].end());
  EXPECT_EQ(results(a_aac), results(b));
  EXPECT_EQ(a["boxes"][0], b["boxes"][0]);
  EXPECT_EQ(a["boxes"][1], b["boxes"][1]);
  EXPECT_EQ(a["wilcoxon"][0], b["wilcoxon"][0]);

  // What the report holds for 2 missions x 2 conditions x 2 designs.
  EXPECT_EQ(a["experiment"]["state"], "finished");
  EXPECT_EQ(a["designs"].size(), 8u);
  EXPECT_EQ(a["boxes"].size(), 4u);
  EXPECT_EQ(a["wilcoxon"].size(), 2u);  // alone vs combined, per mission
  ASSERT_TRUE(a["friedman"].is_object());
  EXPECT_EQ(a["friedman"]["blocks"].size(), 2u);
  for (const auto& d : a["designs"]) {
    EXPECT_EQ(d["scores"].size(), 3u);
    EXPECT_FALSE(d["convergence"].empty());
    EXPECT_LE(d["runs_used"].get<int>(), d["budget"].get<int>());
    if (d["condition"] == "alone") {
      EXPECT_EQ(d["architecture"], d["mission"] == "foraging" ? "bt" : "fsm");  // Maple designs trees
      for (const int id : d["modules"]["behaviours"]) EXPECT_EQ(id / 10, d["mission"] == "foraging" ? 4 : 1);
    }
  }
  const auto folder = scratch() / "killed-report";
  EXPECT_TRUE(std::filesystem::exists(folder / "report.html"));
  EXPECT_EQ(csv_rows(folder / "designs.csv"), 8);
  EXPECT_EQ(csv_rows(folder / "assessments.csv"), 24);
  EXPECT_EQ(csv_rows(folder / "boxes.csv"), 4);
  EXPECT_EQ(csv_rows(folder / "friedman.csv"), 2);
}

TEST_F(experiment, AnotherExperimentReusesTheDesignsItAlreadyHas) {
  user_with_active_project("alice", "thesis");
  const std::string mission = write_short_mission(scratch()).string();
  const auto protocol = write_file("mini.json", R"({"name": "mini", "designs": 2, "assessment_seeds": 3, "missions": [
      {"mission": ")" + mission + R"(", "budget": 1008, "conditions": [
        {"name": "alone", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  run_ok({"experiment", "--file", protocol.string()});
  const auto larger = write_file("larger.json", R"({"name": "larger", "designs": 2, "assessment_seeds": 3, "missions": [
      {"mission": ")" + mission + R"(", "budget": 1008, "conditions": [
        {"name": "alone", "architectures": ["fsm"], "flavours": ["chocolate"]},
        {"name": "trees", "architectures": ["bt"], "flavours": ["chocolate"]}]}]})");
  const std::string out = run_ok({"experiment", "--file", larger.string()});
  EXPECT_NE(out.find("the same design as mini's #1 of alone"), std::string::npos) << out;
  EXPECT_NE(out.find("the same design as mini's #2 of alone"), std::string::npos) << out;
  EXPECT_EQ(query("SELECT count(*) FROM experiment_designs WHERE reused_from IS NOT NULL"), "2");

  const json first = report("mini", "thesis", scratch() / "mini");
  const json second = report("larger", "thesis", scratch() / "larger");
  ASSERT_EQ(second["designs"].size(), 4u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(first["designs"][i]["configuration"], second["designs"][i]["configuration"]);
    EXPECT_EQ(first["designs"][i]["scores"], second["designs"][i]["scores"]);  // assessed again: same seeds
    EXPECT_EQ(second["designs"][i]["reused_from"], first["designs"][i]["id"]);
  }
  EXPECT_TRUE(second["designs"][2]["reused_from"].is_null());
  // One mission: no Friedman test across missions, and the report says so with null.
  EXPECT_TRUE(second["friedman"].is_null());
}

TEST_F(experiment, TheEvoStickBaselineIsAConditionLikeAnyOther) {
  user_with_active_project("alice", "thesis");
  const std::string mission = write_short_mission(scratch()).string();
  const auto protocol = write_file("evo.json", R"({"name": "evo", "designs": 1, "assessment_seeds": 2, "missions": [
      {"mission": ")" + mission + R"(", "budget": 1500, "conditions": [
        {"name": "alone", "architectures": ["fsm"], "flavours": ["chocolate"]},
        {"name": "evostick", "method": "evostick"}]}]})");
  const Outcome out = run({"experiment", "--file", protocol.string()});
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_NE(out.err.find("whole generations of 1000 runs: budget 1500 becomes 1000"), std::string::npos) << out.err;
  const json r = report("evo", "thesis", scratch() / "evo");
  ASSERT_EQ(r["designs"].size(), 2u);
  const json& evo = r["designs"][1];
  EXPECT_EQ(evo["condition"], "evostick");
  EXPECT_EQ(evo["architecture"], "nn");
  EXPECT_EQ(evo["runs_used"], 1000);
  EXPECT_EQ(evo["convergence"].size(), 1u);  // one generation
  EXPECT_EQ(evo["configuration"].get<std::string>().rfind("--nn-config", 0), 0u);
  EXPECT_TRUE(evo["modules"]["behaviours"].empty());
  EXPECT_EQ(r["architectures"][1]["nn"], 1);
}

TEST_F(experiment, TheDesignMethodsAreConditionsLikeAnyOtherEachDesignMadeByItsOwnMethod) {
  // The "methods" protocol's conditions at a small scale: one mission, one design each.
  user_with_active_project("alice", "thesis");
  const std::string mission = write_short_mission(scratch()).string();
  const auto protocol = write_file("methods.json", R"({"name": "methods-small", "designs": 1, "assessment_seeds": 2, "missions": [
      {"mission": ")" + mission + R"(", "budget": 1100, "conditions": [
        {"name": "automode", "method": "automode", "architectures": ["fsm"], "flavours": ["chocolate"]},
        {"name": "random-search", "method": "random-search", "architectures": ["fsm"], "flavours": ["chocolate"]},
        {"name": "local-search", "method": "local-search", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  run_ok({"experiment", "--file", protocol.string()});
  const json r = report("methods-small", "thesis", scratch() / "methods");
  ASSERT_EQ(r["designs"].size(), 3u);
  for (const auto& d : r["designs"]) {
    const std::string method = d["condition"];
    // The same design as `design --method` makes from the seed the experiment gave it.
    const json alone = design_outcome(run_ok({"design", "--mission", mission, "--budget", "1100", "--fsm", "--chocolate",
                                              "--seed", std::to_string(d["seed"].get<std::uint64_t>()), "--method", method,
                                              "--threads", "2", "--json", "--out",
                                              (scratch() / (method + "-" + d["replicate"].dump())).string()}));
    EXPECT_EQ(d["configuration"], alone["best"]["configuration"]) << method;
    EXPECT_EQ(d["runs_used"], alone["experiments_used"]) << method;
  }
}

TEST_F(experiment, DryRunCountsTheRunsAndMeasuresTheTime) {
  const json plan = json::parse(run_ok({"experiment", "validation", "--dry-run", "--json"}));
  EXPECT_EQ(plan["designs"].size(), 50u);  // 5 missions x 1 condition x 10 designs
  EXPECT_EQ(plan["design_runs"], 10 * (200000 + 50000 + 100000 + 100000 + 200000));
  EXPECT_EQ(plan["assessment_runs"], 50 * 20);
  EXPECT_GT(plan["estimate"]["seconds"].get<double>(), 0.0);
  EXPECT_EQ(plan["estimate"]["missions"].size(), 5u);

  const json small = json::parse(
      run_ok({"experiment", "architecture", "--dry-run", "--json", "--missions", "aac", "--designs", "1", "--budget-scale", "0.05"}));
  ASSERT_EQ(small["designs"].size(), 2u);
  EXPECT_EQ(small["designs"][0]["architectures"], "fsm");
  EXPECT_EQ(small["designs"][1]["architectures"], "bt");
  EXPECT_EQ(small["designs"][0]["budget"], 10000);
  EXPECT_EQ(small["designs"][0]["flavours"], "chocolate,tuttifrutti,coconut,maple,arlequin");
}

TEST_F(experiment, MalformedProtocolsAreRefusedNamingTheFieldAndStoreNothing) {
  user_with_active_project("alice", "thesis");
  const std::string before = snapshot();
  const auto typo = write_file("typo.json", R"({"name": "x", "missions": [{"mission": "aac", "budget": 1000,
      "conditions": [{"name": "a", "architectures": ["fsm"], "flavours": ["chocolate", "vanila"]}]}]})");
  expect_error(run({"experiment", "--file", typo.string()}), 2, "missions[0].conditions[0].flavours[1]: unknown 'vanila'");
  const auto budget = write_file("budget.json", R"({"name": "x", "missions": [{"mission": "aac", "budget": -5,
      "conditions": [{"name": "a", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  expect_error(run({"experiment", "--file", budget.string()}), 2, "missions[0].budget: must be between 1");
  const auto unknown = write_file("unknown.json", R"({"name": "x", "desings": 3, "missions": []})");
  expect_error(run({"experiment", "--file", unknown.string()}), 2, "desings: unknown field");
  const auto broken = write_file("broken.json", R"({"name": "x", )");
  expect_error(run({"experiment", "--file", broken.string()}), 2, "not a JSON document");
  const auto mission = write_file("mission.json", R"({"name": "x", "missions": [{"mission": "no-such-mission", "budget": 1000,
      "conditions": [{"name": "a", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  expect_error(run({"experiment", "--file", mission.string()}), 2, "no-such-mission");
  expect_error(run({"experiment", "validaton"}), 2, "unknown experiment 'validaton'");
  expect_error(run({"experiment", "validation", "--missions", "aac,sca"}), 2, "has no mission 'sca'");
  expect_error(run({"experiment", "validation", "--budget-scale", "0"}), 2, "--budget-scale");
  expect_error(run({"report", "validation"}), 1, "has no experiment 'validation'");
  EXPECT_EQ(snapshot(), before);
}

TEST_F(experiment, TheSameNameWithAnotherProtocolIsRefused) {
  user_with_active_project("alice", "thesis");
  const std::string mission = write_short_mission(scratch()).string();
  const auto protocol = write_file("mini.json", R"({"name": "mini", "designs": 1, "assessment_seeds": 2, "missions": [
      {"mission": ")" + mission + R"(", "budget": 1008, "conditions": [
        {"name": "alone", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  run_ok({"experiment", "--file", protocol.string()});
  expect_error(run({"experiment", "--file", protocol.string(), "--designs", "2"}), 1, "--name");
  // Repeating the first command finds it finished and runs nothing.
  EXPECT_NE(run_ok({"experiment", "--file", protocol.string()}).find("has already finished"), std::string::npos);
  EXPECT_EQ(query("SELECT count(*) FROM experiment_designs"), "1");
}

}  // namespace
}  // namespace sd::test
