// Assessing control software across the reality gap: the design-model runs are the plain
// evaluation's, each pseudo-reality run is the evaluation of the mission in that sample, the
// statistics agree with the scores they summarise, and nothing depends on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include <nlohmann/json.hpp>

#include "app/assess_job.hpp"
#include "app/errors.hpp"
#include "app/evaluation_job.hpp"
#include "app/pseudo_realities.hpp"
#include "control/config_string.hpp"
#include "missions/catalogue.hpp"

namespace sd {
namespace {

// Phototaxis reads light: the IRIDIA pseudo-reality's light noise 0.9 must cost it.
const char* kPhototaxis = "--fsm-config --nstates 1 --s0 2";
const char* kAttraction = "--fsm-config --nstates 1 --s0 4 --att0 3";
const char* kStop = "--fsm-config --nstates 1 --s0 1";

app::AssessRequest request(const std::string& spec, std::vector<const char*> software, int threads = 2) {
  app::AssessRequest r;
  for (const char* s : software) r.software.push_back({s, parse_control_software(s)});
  r.spec = app::load_requested_pseudo_reality(spec).spec;
  r.spec_reference = spec;
  r.samples = {1, 2, 3};
  r.seeds = {1, 2, 3, 4, 5, 6};
  r.threads = threads;
  return r;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }

TEST(Assess, DesignModelRunsAreThePlainEvaluationAndEachSampleIsTheMissionInThatSample) {
  const Mission mission = load_mission("lcn");  // range-and-bearing and proximity: deviations act
  const app::AssessRequest r = request("sampled-around", {kAttraction});
  const app::Assessment a = app::assess(mission, r);
  ASSERT_EQ(a.software.size(), 1u);
  const app::SoftwareAssessment& s = a.software[0];
  EXPECT_EQ(s.design_scores, app::score_seeds(mission, r.software[0].software, r.seeds));
  for (std::size_t k = 0; k < r.samples.size(); ++k) {
    const Mission in_sample = app::in_pseudo_reality(mission, r.spec, r.samples[k]);
    const std::vector<double> expected = app::score_seeds(in_sample, r.software[0].software, r.seeds);
    const std::vector<double> got(s.reality_scores.begin() + static_cast<long>(k * r.seeds.size()),
                                  s.reality_scores.begin() + static_cast<long>((k + 1) * r.seeds.size()));
    EXPECT_EQ(got, expected) << "sample " << r.samples[k];
    EXPECT_NE(got, s.design_scores) << "a pseudo-reality must change the runs";
  }
  EXPECT_EQ(a.models.size(), 3u);
  EXPECT_TRUE(a.models[0].has_deviations());
}

TEST(Assess, AFixedSpecificationsSamplesAreOneModelRunOnceAndCountedForEach) {
  const Mission mission = load_mission("aac");
  app::AssessRequest r = request("iridia-transfer", {kPhototaxis, kAttraction});
  std::size_t runs = 0;
  r.progress = [&](std::size_t, std::size_t all) { runs = all; };
  const app::Assessment a = app::assess(mission, r);
  EXPECT_EQ(a.distinct_models, 1);
  EXPECT_EQ(runs, 2u * 6u * (1u + 1u)) << "each software: the design model and the one model, on 6 seeds";
  for (const app::SoftwareAssessment& s : a.software) {
    const Mission in_sample = app::in_pseudo_reality(mission, r.spec, 1);
    const std::vector<double> expected = app::score_seeds(in_sample, parse_control_software(s.configuration), r.seeds);
    for (std::size_t k = 0; k < r.samples.size(); ++k)
      EXPECT_EQ(std::vector<double>(s.reality_scores.begin() + static_cast<long>(k * 6), s.reality_scores.begin() + static_cast<long>((k + 1) * 6)),
                expected) << s.label << " sample " << r.samples[k];
  }
  // A specification that varies: every sample is its own model.
  EXPECT_EQ(app::assess(mission, request("sampled-around", {kAttraction})).distinct_models, 3);
}

TEST(Assess, TheDropAndItsIntervalSummariseTheScores) {
  const Mission mission = load_mission("aac");
  const app::Assessment a = app::assess(mission, request("iridia-transfer", {kPhototaxis, kAttraction, kStop}));
  for (const auto& s : a.software) {
    EXPECT_DOUBLE_EQ(s.design_mean, mean(s.design_scores));
    EXPECT_DOUBLE_EQ(s.reality_mean, mean(s.reality_scores));
    EXPECT_NEAR(s.drop, s.design_mean - s.reality_mean, 1e-9);  // AAC is maximised: a drop is a loss
    EXPECT_LE(s.drop_low, s.drop + 1e-9);
    EXPECT_GE(s.drop_high, s.drop - 1e-9);
    EXPECT_GE(s.p_value, 0.0);
    EXPECT_LE(s.p_value, 1.0);
    EXPECT_EQ(s.sample_ranks.size(), 3u);
  }
  // Ranks follow the means in each world; an inverted pair is one whose order differs.
  int inverted = 0;
  for (std::size_t i = 0; i < a.software.size(); ++i)
    for (std::size_t j = i + 1; j < a.software.size(); ++j) {
      const auto& x = a.software[i];
      const auto& y = a.software[j];
      EXPECT_EQ(x.design_mean > y.design_mean, x.design_rank < y.design_rank);
      EXPECT_EQ(x.reality_mean > y.reality_mean, x.reality_rank < y.reality_rank);
      inverted += (x.design_mean - y.design_mean) * (x.reality_mean - y.reality_mean) < 0 ? 1 : 0;
    }
  EXPECT_EQ(a.inverted_pairs, inverted);
  EXPECT_EQ(a.pairs, 3);
  EXPECT_GE(a.rank_correlation, -1.0);
  EXPECT_LE(a.rank_correlation, 1.0);
  // The stop controller's robots never move: only their start counts, in any robot model.
  EXPECT_EQ(a.software[2].design_scores, std::vector<double>(a.software[2].reality_scores.begin(),
                                                               a.software[2].reality_scores.begin() + 6));
}

TEST(Assess, ScoresDoNotDependOnTheThreadCount) {
  const Mission mission = load_mission("aac");
  const app::Assessment one = app::assess(mission, request("sampled-around", {kAttraction, kPhototaxis}, 1));
  const app::Assessment two = app::assess(mission, request("sampled-around", {kAttraction, kPhototaxis}, 2));
  for (std::size_t i = 0; i < one.software.size(); ++i) {
    EXPECT_EQ(one.software[i].design_scores, two.software[i].design_scores);
    EXPECT_EQ(one.software[i].reality_scores, two.software[i].reality_scores);
  }
}

TEST(Assess, ASpecificationAtTheDesignValuesChangesNoRun) {
  // Every knob named, each at the design model's value: the pseudo-reality code paths with
  // their knobs at zero must run exactly as the design model does.
  const Mission mission = load_mission("lcn");
  nlohmann::json knobs = nlohmann::json::object();
  for (const RobotKnob& knob : kRobotKnobs) knobs[std::string(knob.name)] = mission.robot.*(knob.member);
  app::AssessRequest r = request("iridia-transfer", {kAttraction, kPhototaxis});
  r.spec = parse_pseudo_reality(nlohmann::json{{"knobs", knobs}}.dump(), "same.json");
  const app::Assessment a = app::assess(mission, r);
  for (const auto& s : a.software)
    for (std::size_t k = 0; k < r.samples.size(); ++k)
      EXPECT_EQ(std::vector<double>(s.reality_scores.begin() + static_cast<long>(k * r.seeds.size()),
                                    s.reality_scores.begin() + static_cast<long>((k + 1) * r.seeds.size())),
                s.design_scores);
}

TEST(Assess, RefusesEmptyRequestsAndStopsWhenCancelled) {
  const Mission mission = load_mission("aac");
  app::AssessRequest r = request("iridia-transfer", {kAttraction});
  r.seeds.clear();
  EXPECT_THROW(app::assess(mission, r), app::InvalidRequest);
  r = request("iridia-transfer", {});
  EXPECT_THROW(app::assess(mission, r), app::InvalidRequest);
  r = request("iridia-transfer", {kAttraction});
  app::CancelToken token;
  token.cancel();
  r.cancel = &token;
  EXPECT_THROW(app::assess(mission, r), app::AssessCancelled);
}

TEST(Assess, SampleRangesAreBoundedAndNumberedFromOne) {
  EXPECT_EQ(app::parse_sample_range("3-5"), (std::vector<std::uint64_t>{3, 4, 5}));
  EXPECT_THROW(app::parse_sample_range("0-3"), app::InvalidRequest);
  EXPECT_THROW(app::parse_sample_range("1-20000"), app::InvalidRequest);
  EXPECT_THROW(app::parse_sample_range("x"), app::InvalidRequest);
  EXPECT_THROW(app::load_requested_pseudo_reality("nowhere"), app::InvalidRequest);
}

}  // namespace
}  // namespace sd
