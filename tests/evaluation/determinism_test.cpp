// (mission, control software, seed) -> score is a pure function, whatever the threads.
#include <gtest/gtest.h>

#include <atomic>
#include <sstream>
#include <string>
#include <utility>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"
#include "evaluation/simulation.hpp"
#include "evaluation/trace_writer.hpp"
#include "missions/catalogue.hpp"
#include "missions/mission.hpp"

namespace sd {
namespace {

const char* kAttractStop =
    "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 "
    "--s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";

TEST(Determinism, SameSeedGivesTheSameScoreAndTraceBitForBit) {
  const Mission m = load_mission("aac");
  const ControlSoftware sw = parse_control_software(std::string(kAttractStop));
  std::ostringstream a, b;
  TraceWriter wa(a), wb(b);
  Simulation s1(m, sw), s2(m, sw);
  const double x = s1.run(5, &wa);
  const double y = s2.run(5, &wb);
  EXPECT_EQ(x, y);
  EXPECT_EQ(a.str(), b.str());
  EXPECT_GT(a.str().size(), 1200u * 20u * 20u);  // one row per robot per tick
  // A reused simulation gives the same again.
  EXPECT_EQ(s1.run(5), x);
}

TEST(Determinism, DifferentSeedsGiveDifferentRuns) {
  const Mission m = load_mission("aac");
  const ControlSoftware sw = parse_control_software(std::string(kAttractStop));
  EXPECT_NE(evaluate(m, sw, 1), evaluate(m, sw, 2));
}

TEST(Determinism, ScoresDoNotDependOnTheThreadCount) {
  const Mission m = load_mission("aac");
  const ControlSoftware a = parse_control_software(std::string(kAttractStop));
  const ControlSoftware b = parse_control_software(std::string("--fsm-config --nstates 1 --s0 10 --rwm0 50"));
  std::vector<EvaluationTask> tasks;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) tasks.push_back({seed % 2 ? &a : &b, seed});
  std::vector<double> one(tasks.size()), two(tasks.size()), three(tasks.size());
  ThreadedEvaluator(1).evaluate(m, tasks, one);
  ThreadedEvaluator(2).evaluate(m, tasks, two);
  ThreadedEvaluator(3).evaluate(m, tasks, three);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, three);
  for (std::size_t i = 0; i < tasks.size(); ++i) EXPECT_EQ(one[i], evaluate(m, *tasks[i].software, tasks[i].seed));
}

TEST(Determinism, ARaisedStopFlagStopsABatchAndALoweredOneChangesNothing) {
  const Mission m = load_mission("aac");
  const ControlSoftware a = parse_control_software("--fsm-config --nstates 1 --s0 0 --rwm0 50");
  std::vector<EvaluationTask> tasks;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) tasks.push_back({&a, seed});
  std::vector<double> plain(tasks.size()), flagged(tasks.size()), stopped(tasks.size(), -7.0);
  ThreadedEvaluator(2).evaluate(m, tasks, plain);
  std::atomic<bool> stop{false};
  ThreadedEvaluator evaluator(2);
  evaluator.stop_when(&stop);
  evaluator.evaluate(m, tasks, flagged);
  EXPECT_EQ(plain, flagged);  // a flag never raised: the same scores, bit for bit
  stop.store(true);
  EXPECT_THROW(evaluator.evaluate(m, tasks, stopped), EvaluationStopped);
  EXPECT_EQ(stopped, std::vector<double>(tasks.size(), -7.0)) << "no run after the stop";
  evaluator.stop_when(nullptr);
  evaluator.evaluate(m, tasks, stopped);
  EXPECT_EQ(plain, stopped);
}

/// One run's score and trace, pairs found one way or the other.
std::pair<double, std::string> traced_run(const Mission& m, const ControlSoftware& sw, std::uint64_t seed, bool grid) {
  std::ostringstream trace;
  TraceWriter writer(trace);
  Simulation simulation(m, sw);
  simulation.use_neighbour_grid(grid);
  const double score = simulation.run(seed, &writer);
  return {score, trace.str()};
}

TEST(Determinism, RunsDoNotDependOnHowPairsAreFound) {
  // Each sensor that looks at other robots: range and bearing and proximity (attraction),
  // light with occlusion by bodies (phototaxis), the camera (TuttiFrutti's T10), and walls
  // added after placement (SCA).
  const char* kPhototaxis = "--fsm-config --nstates 2 --s0 4 --att0 3 --n0 1 --n0x0 0 --c0x0 5 --p0x0 0.2 --s1 1 --n1 0";
  const struct {
    const char* mission;
    std::string software;
    Flavour legacy;
  } runs[] = {
      {"aac", kAttractStop, Flavour::Chocolate},
      {"aac", kPhototaxis, Flavour::Chocolate},
      {"sca", kPhototaxis, Flavour::Chocolate},
      {"tutti-aggregation",
       "--fsm-config --nstates 2 --s0 8 --vel0 1.0 --cle0 5 --clr0 4 --n0 1 --n0x0 0 --c0x0 4 --p0x0 1 --w0x0 11.51 "
       "--s1 5 --rep1 2.87 --cle1 6 --n1 1 --n1x0 0 --c1x0 0 --p1x0 0.15",
       Flavour::TuttiFrutti},
  };
  for (const auto& r : runs) {
    const Mission m = load_mission(r.mission);
    const ControlSoftware sw = parse_control_software(r.software, {r.legacy});
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const auto [full_score, full_trace] = traced_run(m, sw, seed, false);
      const auto [grid_score, grid_trace] = traced_run(m, sw, seed, true);
      EXPECT_EQ(full_score, grid_score) << r.mission << " seed " << seed << ": " << r.software;
      EXPECT_TRUE(full_trace == grid_trace) << r.mission << " seed " << seed << ": the traces differ";
    }
  }
}

TEST(Determinism, ALargeSwarmRunsTheSameWithOrWithoutTheGrid) {
  // 400 robots in AAC's density (its arena scaled by sqrt(20)): more pairs than 16-bit
  // indices reach, and a grid of many cells.
  const std::string mission_text = R"({
    "name": "aac-400", "duration": 3, "robots": 400,
    "arena": {
      "walls": [{"regular_polygon": {"sides": 12, "apothem": 5.505, "length": 2.952, "thickness": 0.01, "height": 0.08}}],
      "floor": {"background": "gray", "patches": [{"region": {"circle": {"center": [0, 2.683], "radius": 1.342}}, "color": "black"}]},
      "lights": [{"position": [0, -6.708, 0.4], "intensity": 3.0, "color": "yellow"}]
    },
    "start": {"circle": {"center": [0, 0], "radius": 5.367}},
    "objective": {"type": "robots_in_region_per_tick", "region": {"circle": {"center": [0, 2.683], "radius": 1.342}}, "direction": "maximize"}
  })";
  const Mission m = parse_mission(mission_text, "test");
  const ControlSoftware sw = parse_control_software(std::string(kAttractStop));
  const auto [full_score, full_trace] = traced_run(m, sw, 7, false);
  const auto [grid_score, grid_trace] = traced_run(m, sw, 7, true);
  EXPECT_EQ(full_score, grid_score);
  EXPECT_TRUE(full_trace == grid_trace) << "the traces differ";
}

}  // namespace
}  // namespace sd
