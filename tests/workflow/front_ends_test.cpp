// One core, three thin front ends (issue #54): the same request gives the same document, bit
// for bit, from the CLI's --json and from the web's API, because both only parse and call the
// application layer's service (app/test_design, app/export_argos). Python's side of the same
// comparison is tests/python/test_front_ends.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/served_workflow.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

class front_ends : public ServedWorkflowTest {
 protected:
  void SetUp() override {
    ServedWorkflowTest::SetUp();
    user_with_active_project("ada", "p");
    // In the project's own folder: the web reads a user's mission files only there.
    const auto mission = write_short_mission(home() / "users" / "ada" / "projects" / "p", 2);
    run_ok({"set-mission", mission.string()});
    run_ok({"set-budget", "1100"});
    run_ok({"run-design", "--fsm", "--chocolate", "--seed", "1", "--threads", "2"});
    run_ok({"run-design", "--fsm", "--chocolate", "--seed", "2", "--threads", "2"});
    serve();
    browser_.emplace(port());
    ASSERT_TRUE(browser_->sign_in("ada", "ada-secret-pw")) << browser_->last_refusal();
  }
  void TearDown() override {
    browser_.reset();
    ServedWorkflowTest::TearDown();
  }
  json web(const std::string& route, const json& body) {
    const Answer answer = browser_->post("/api/projects/p/" + route, body);
    EXPECT_EQ(answer.status, 200) << answer.text;
    return answer.body;
  }

  std::optional<WebClient> browser_;
};

TEST_F(front_ends, TestingADesignGivesOneDocumentFromTheCliAndTheWeb) {
  const json cli = json::parse(run_ok({"test-design", "--design", "1", "--seeds", "3-6", "--json"}));
  EXPECT_EQ(cli, web("test", {{"design", 1}, {"seeds", "3-6"}}));
  EXPECT_EQ(cli["design"], 1);
  EXPECT_EQ(cli["runs"].size(), 4u);
  // The default: the last design with a best.
  EXPECT_EQ(json::parse(run_ok({"test-design", "--seeds", "1-2", "--json"})), web("test", {{"seeds", "1-2"}}));
}

TEST_F(front_ends, ComparingTwoDesignsGivesOneDocumentFromTheCliAndTheWeb) {
  const json cli = json::parse(run_ok({"compare-designs", "1", "2", "--seeds", "1-8", "--json"}));
  EXPECT_EQ(cli, web("compare", {{"designs", {1, 2}}, {"seeds", "1-8"}}));
  ASSERT_EQ(cli["designs"].size(), 2u);
  EXPECT_EQ(cli["designs"][0]["design"], 1);
  EXPECT_EQ(cli["designs"][1]["design"], 2);
  EXPECT_EQ(cli["wilcoxon"]["test"], "Wilcoxon signed-rank, paired by seed");
  // Each side is what test-design gives for that design on those seeds.
  EXPECT_EQ(cli["designs"][1], json::parse(run_ok({"test-design", "--design", "2", "--seeds", "1-8", "--json"})));
  // The text says the same.
  const std::string text = run_ok({"compare-designs", "1", "2", "--seeds", "1-8"});
  EXPECT_NE(text.find("Wilcoxon signed-rank, paired by seed"), std::string::npos) << text;
  expect_error(run({"compare-designs", "1", "9"}), 1, "has no design 9");
}

TEST_F(front_ends, ADesignForArgosIsOneDocumentFromTheCliAndTheWebAndItsFileIsWritten) {
  const auto out = scratch() / "p.argos";
  const json cli = json::parse(run_ok({"export-argos", "--design", "2", "--out", out.string(), "--pseudo-reality",
                                       "sampled-around", "--sample", "3", "--json"}));
  EXPECT_EQ(cli, web("argos", {{"design", 2}, {"pseudo_reality", "sampled-around"}, {"sample", "3"}}));
  std::stringstream written;
  written << std::ifstream(out).rdbuf();
  EXPECT_EQ(written.str(), cli["experiment"].get<std::string>());
  EXPECT_EQ(cli["pseudo_reality"]["sample"], "3");
  // The sample is the one the simulator runs: its noise differs from the design model's file.
  EXPECT_NE(cli["experiment"], web("argos", {{"design", 2}})["experiment"]);
  EXPECT_EQ(json::parse(run_ok({"export-argos", "--design", "2", "--out", out.string(), "--json"})),
            web("argos", {{"design", 2}}));
}

// The new requests refuse bad input in one line and write nothing; the page reads only the
// user's own files (another account's specification, a path outside, a device).
TEST_F(front_ends, AnExperimentsPlanIsOneDocumentFromTheCliAndTheWeb) {
  json cli = json::parse(run_ok({"experiment", "validation", "--missions", "aac", "--designs", "3", "--seed", "5",
                                 "--budget-scale", "0.01", "--dry-run", "--json", "--threads", "1"}));
  const json request = {{"protocol", "validation"}, {"missions", {"aac"}}, {"designs", 3}, {"seed", "5"},
                        {"budget_scale", 0.01}, {"dry_run", true}};
  const json cli_estimate = cli["estimate"];  // measured now: only its runs are the same
  cli.erase("estimate");
  EXPECT_EQ(cli, web("experiments", request));
  // The page's Plan asks for the estimate too: the same runs, timed on the server's threads.
  json estimated = request;
  estimated["estimate"] = true;
  json page = web("experiments", estimated);
  ASSERT_TRUE(page.contains("estimate")) << page.dump();
  EXPECT_EQ(page["estimate"]["missions"][0]["runs"], cli_estimate["missions"][0]["runs"]);
  EXPECT_GT(page["estimate"]["seconds"].get<double>(), 0.0);
  page.erase("estimate");
  EXPECT_EQ(cli, page);
  // Nothing was started by planning.
  EXPECT_EQ(browser_->get("/api/projects/p/experiments").body, json::array());
}

TEST_F(front_ends, AnAssessmentOfADesignIsOneDocumentFromTheCliAndTheWeb) {
  json cli = json::parse(run_ok({"assess", "--project-design", "2", "--pseudo-reality", "sampled-around", "--samples",
                                 "1-2", "--seeds", "1-3", "--json"}));
  json page = web("designs/2/assessment", {{"pseudo_reality", "sampled-around"}, {"samples", "1-2"}, {"seeds", "1-3"}});
  ASSERT_TRUE(page.contains("request")) << page.dump();
  page.erase("request");  // the page keeps what it asked for beside the design
  cli.erase("seconds");   // each one's own wall time
  page.erase("seconds");
  EXPECT_EQ(cli, page);
  ASSERT_EQ(cli["software"].size(), 1u);
  EXPECT_EQ(cli["software"][0]["runs"].size(), 3u * (1u + 2u)) << cli["software"][0].dump();
  // Its CSV (app::assessment_csv): one row per run, with the JSON's scores.
  const auto csv = scratch() / "assess.csv";
  run_ok({"assess", "--project-design", "2", "--pseudo-reality", "sampled-around", "--samples", "1-2", "--seeds", "1-3",
          "--csv", csv.string()});
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "software,world,sample,seed,score");
  for (const json& run : cli["software"][0]["runs"]) {
    ASSERT_TRUE(std::getline(in, line));
    const bool design = run["sample"] == 0;
    std::ostringstream want;
    want.precision(17);
    want << "\"design 2 best\"," << (design ? "design" : "pseudo-reality") << "," << run["sample"].get<int>() << ","
         << run["seed"].get<int>() << "," << run["score"].get<double>();
    EXPECT_EQ(line, want.str());
  }
  EXPECT_FALSE(std::getline(in, line)) << line;
}

TEST_F(front_ends, BadRequestsAreOneLineRefusalsAndThePageReadsOnlyTheUsersFiles) {
  expect_error(run({"compare-designs", "1"}), 2, "b is required");
  expect_error(run({"compare-designs", "1", "2", "--seeds", "9-1"}), 2, "seed");
  expect_error(run({"test-design", "--design", "1", "--fsm-config", "--nstates", "1", "--s0", "10", "--rwm0", "50"}), 2, "not both");
  expect_error(run({"export-argos", "--design", "2", "--sample", "3", "--out", (scratch() / "x.argos").string()}), 2,
               "go together");
  expect_error(run({"export-argos", "--design", "2", "--pseudo-reality", "sampled-around", "--sample", "1-3", "--out",
                    (scratch() / "x.argos").string()}), 2, "one sample number");
  EXPECT_FALSE(std::filesystem::exists(scratch() / "x.argos"));
  expect_error(run({"evaluate", "--mission", "aac", "--sample", "2", "--fsm-config", "--nstates", "1", "--s0", "10", "--rwm0", "50"}), 2,
               "go together");
  expect_error(run({"collect", "--project", "nope"}), 1, "nope");

  const auto refused = [&](const std::string& route, const json& body, int status) {
    const Answer answer = browser_->post("/api/projects/p/" + route, body);
    EXPECT_EQ(answer.status, status) << route << " " << body.dump() << ": " << answer.text;
    EXPECT_EQ(answer.text.find('\n'), std::string::npos) << "one line";
  };
  refused("argos", {{"design", 2}, {"pseudo_reality", "/etc/passwd"}, {"sample", "1"}}, 404);
  refused("argos", {{"design", 2}, {"pseudo_reality", "/dev/zero"}, {"sample", "1"}}, 404);
  refused("argos", {{"design", 2}, {"pseudo_reality", "../../../../etc/hostname"}, {"sample", "1"}}, 404);
  refused("argos", {{"design", 2}, {"pseudo_reality", "sampled-around"}, {"sample", "0"}}, 400);
  refused("argos", {{"design", 9}}, 404);
  refused("compare", {{"designs", {1, "2"}}}, 400);
  refused("compare", {{"designs", {1, 2}}, {"seeds", "1-101"}}, 400);  // a page's bound: 100 seeds
  refused("test", {{"design", "1"}}, 400);
  // An experiment's protocol file (the field Python's plan_experiment(file=...) fills) is read
  // only from the user's own projects, and a refusal leaks nothing of what is elsewhere.
  refused("experiments", {{"file", "/etc/passwd"}, {"dry_run", true}}, 404);
  refused("experiments", {{"file", "/dev/zero"}, {"dry_run", true}}, 404);
  refused("experiments", {{"file", "../../../../etc/hostname"}, {"dry_run", true}}, 404);
  refused("experiments", {{"protocol", "validation"}, {"designs", "3"}, {"dry_run", true}}, 400);
  refused("experiments", {{"protocol", "validation"}, {"text", "{}"}, {"dry_run", true}}, 400);
  // Another account's projects are not there at all.
  run_ok({"sign-up", "eve", "--password-stdin"}, "eve-secret-pw\n");
  WebClient eve(port());
  ASSERT_TRUE(eve.sign_in("eve", "eve-secret-pw"));
  EXPECT_EQ(eve.post("/api/projects/p/argos", {{"design", 2}}).status, 404);
  EXPECT_EQ(eve.post("/api/projects/p/compare", {{"designs", {1, 2}}}).status, 404);
}

}  // namespace
}  // namespace sd::test
