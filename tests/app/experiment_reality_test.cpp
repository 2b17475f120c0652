// An experiment whose protocol asks for pseudo-realities (issue #46): every final design is also
// run on its assessment seeds in the pseudo-reality samples, all stored at once; the report puts
// each condition's design-model and pseudo-reality scores side by side with the drop, its paired
// test and the conditions' ranks in both worlds. A tiny protocol (a 2-second mission, the least
// budget, two designs) keeps it fast.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "app/accounts.hpp"
#include "app/assess_job.hpp"
#include "app/errors.hpp"
#include "app/experiment_job.hpp"
#include "app/experiment_report.hpp"
#include "app/projects.hpp"
#include "app/pseudo_realities.hpp"
#include "control/config_string.hpp"
#include "missions/catalogue.hpp"
#include "storage/lease.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

class ExperimentReality : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() / ("sd-experiment-reality-" + std::to_string(::getpid()) + "-" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    home_.emplace(root_);
    user_ = app::sign_up(*home_, "alice", "correct horse battery");
    const auto folder = root_ / "users" / "alice" / "projects" / "p";
    std::filesystem::create_directories(folder);
    app::create_project(*home_, user_, "p", std::nullopt);
    app::select_project(*home_, user_, "p");
    mission_ = write_short_mission(folder, 2).string();
  }
  void TearDown() override {
    home_.reset();
    std::filesystem::remove_all(root_);
  }

  experiments::Protocol tiny(const std::string& name, bool reality) const {
    experiments::Protocol p;
    p.name = name;
    p.designs = 2;
    p.assessment_seeds = 3;
    p.missions = {{mission_, 1, {{"alone", "automode", {"fsm"}, {"chocolate"}}}}};
    if (reality) p.pseudo_reality = experiments::PseudoRealityPlan{"sampled-around", 2, ""};
    return p;
  }
  void run(const experiments::Protocol& protocol) {
    app::StartedExperiment e = app::start_experiment(*home_, user_, app::plan_experiment(protocol),
                                                     {"p", storage::owner_text(storage::local_process())});
    app::run_experiment(e, {.threads = 2, .evaluator = nullptr, .observer = nullptr, .cancel = nullptr});
  }

  std::filesystem::path root_;
  std::optional<app::Home> home_;
  storage::User user_;
  std::string mission_;
};

TEST_F(ExperimentReality, ProtocolsPseudoRealityIsReadWhenPlannedAndCountedInTheRuns) {
  const app::PlannedExperiment plan = app::plan_experiment(tiny("gap", true));
  ASSERT_TRUE(plan.protocol.pseudo_reality);
  const json definition = json::parse(plan.protocol.pseudo_reality->definition);
  EXPECT_TRUE(definition.is_object()) << "the specification is kept with the experiment";
  EXPECT_EQ(definition.value("name", ""), "sampled-around");
  EXPECT_EQ(plan.assessment_runs, 2 * 3 * (1 + 2));
  EXPECT_EQ(app::plan_experiment(tiny("plain", false)).assessment_runs, 2 * 3);
  // Without a pseudo-reality the stored protocol is as before (old experiments resume).
  EXPECT_FALSE(experiments::to_json(app::plan_experiment(tiny("plain", false)).protocol).contains("pseudo_reality"));

  experiments::Protocol bad = tiny("bad", true);
  bad.pseudo_reality->spec = "no-such-world";
  try {
    app::plan_experiment(bad);
    FAIL() << "an unknown pseudo-reality was planned";
  } catch (const app::InvalidRequest& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("pseudo_reality.spec: ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST_F(ExperimentReality, DesignsAreAssessedInBothWorldsAndTheReportShowsTheGap) {
  run(tiny("gap", true));
  const json report = app::experiment_report_document(*home_, user_, "gap", "p");
  ASSERT_EQ(report["designs"].size(), 2u);
  const Mission mission = load_mission(mission_);
  const app::NamedPseudoReality spec = app::load_requested_pseudo_reality("sampled-around");
  for (const json& d : report["designs"]) {
    const json& r = d["pseudo_reality"];
    ASSERT_TRUE(r.is_object()) << d.dump();
    EXPECT_EQ(r["samples"], 2);
    ASSERT_EQ(r["scores"].size(), 2u * 3u);
    ASSERT_EQ(r["by_seed"].size(), 3u);
    EXPECT_LE(r["drop_ci95"][0].get<double>(), r["drop_ci95"][1].get<double>());
    // The stored runs are exactly what `swarmdesign assess` computes for this software.
    app::AssessRequest request;
    request.software = {{"design", parse_control_software(d["configuration"].get<std::string>())}};
    request.spec = spec.spec;
    request.samples = {1, 2};
    for (const auto& seed : d["assessment_seeds"]) request.seeds.push_back(seed.get<std::uint64_t>());
    request.threads = 1;
    const app::Assessment a = app::assess(mission, request);
    EXPECT_EQ(json(a.software[0].design_scores), d["scores"]);
    EXPECT_EQ(json(a.software[0].reality_scores), r["scores"]);
    EXPECT_DOUBLE_EQ(a.software[0].drop, r["drop"].get<double>());
    EXPECT_DOUBLE_EQ(a.software[0].p_value, r["p_value"].get<double>());
  }
  const json& gap = report["pseudo_reality"];
  ASSERT_TRUE(gap.is_object());
  EXPECT_EQ(gap["spec"], "sampled-around");
  EXPECT_EQ(gap["samples"], 2);
  ASSERT_EQ(gap["cells"].size(), 1u);
  EXPECT_EQ(gap["cells"][0]["n"], 2);
  EXPECT_EQ(gap["cells"][0]["design_model"]["values"].size(), 2u);
  EXPECT_EQ(gap["cells"][0]["pseudo_reality"]["values"].size(), 2u);
  ASSERT_EQ(gap["ranks"].size(), 1u);
  EXPECT_EQ(gap["ranks"][0]["design_model_rank"], 1.0);
  EXPECT_TRUE(gap["inversions"].empty());

  // The same designs without pseudo-realities: taken from the first experiment, assessed in the
  // design model alone, to the same scores (one batch of runs or the other, the same bits).
  run(tiny("plain", false));
  const json plain = app::experiment_report_document(*home_, user_, "plain", "p");
  EXPECT_TRUE(plain["pseudo_reality"].is_null());
  ASSERT_EQ(plain["designs"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(plain["designs"][i]["pseudo_reality"].is_null());
    EXPECT_EQ(plain["designs"][i]["scores"], report["designs"][i]["scores"]);
  }
  // Its tables: one row per run in the pseudo-realities, one per design and one per condition.
  int files = 0;
  for (const app::ReportFile& f : app::experiment_report_data_files(report)) {
    const auto lines = std::count(f.content.begin(), f.content.end(), '\n');
    if (f.name == "pseudo_reality_runs.csv") {
      EXPECT_EQ(lines, 1 + 2 * 2 * 3);
    } else if (f.name == "pseudo_reality_designs.csv") {
      EXPECT_EQ(lines, 1 + 2);
    } else if (f.name == "pseudo_reality.csv") {
      EXPECT_EQ(lines, 1 + 1);
    }
    files += f.name.starts_with("pseudo_reality") ? 1 : 0;
  }
  EXPECT_EQ(files, 3);
  for (const app::ReportFile& f : app::experiment_report_data_files(plain)) EXPECT_FALSE(f.name.starts_with("pseudo_reality"));
}

}  // namespace
}  // namespace sd::test
