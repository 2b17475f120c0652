// (mission, control software, seed) -> score is a pure function, whatever the threads.
#include <gtest/gtest.h>

#include <sstream>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"
#include "evaluation/simulation.hpp"
#include "evaluation/trace_writer.hpp"
#include "missions/catalogue.hpp"

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

}  // namespace
}  // namespace sd
