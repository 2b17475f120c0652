// The same binary must score a run the same on every x86-64 CPU. glibc runs FMA code for sin,
// cos, exp, log and atan2 on CPUs that have FMA and SSE2 code on the others, and the two
// differ in the last bit now and then; SwarmDesign therefore uses its own (core/math.hpp).
// GLIBC_TUNABLES makes glibc take its SSE2 paths here, as on an older CPU: the scores,
// the trace and a short design must not change. (On a CPU without FMA both runs take the
// same paths, and the test checks only that the setting is harmless.)
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

class cross_cpu : public WorkflowTest {
 protected:
  Environment without_fma() const {
    Environment e = environment();
    e.set["GLIBC_TUNABLES"] = "glibc.cpu.hwcaps=-AVX2,-FMA";
    return e;
  }
  static std::string read(const std::filesystem::path& file) {
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
  }
};

TEST_F(cross_cpu, RunsScoreTheSameWithAndWithoutGlibcsFmaCode) {
  // Attraction and a random walk with obstacle avoidance: headings turn both ways, bearings
  // and wheel noise are drawn every tick, so every function of core/math.hpp is exercised.
  const std::vector<std::string> software = {
      "--fsm-config", "--nstates", "2", "--s0", "14", "--att0", "5", "--n0", "1", "--n0x0", "0", "--c0x0", "10",
      "--p0x0", "1.0", "--s1", "10", "--rwm1", "20", "--n1", "1", "--n1x0", "0", "--c1x0", "11", "--p1x0", "0.1"};
  auto args = [&](std::vector<std::string> a) {
    a.insert(a.end(), software.begin(), software.end());
    return a;
  };
  const auto scores = args({"evaluate", "--mission", "aac", "--seeds", "1-4", "--threads", "2"});
  const Outcome with = run_swarmdesign(scores, "", environment());
  const Outcome without = run_swarmdesign(scores, "", without_fma());
  ASSERT_EQ(with.exit_code, 0) << with.err;
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_NE(with.out.find("Score"), std::string::npos);
  EXPECT_EQ(with.out, without.out);
  // Every tick's poses (to 9 digits) and running objective (to 17).
  auto traced = [&](const std::string& file) {
    return args({"evaluate", "--mission", "aac", "--seed", "2", "--trace", (scratch() / file).string()});
  };
  ASSERT_EQ(run_swarmdesign(traced("with.trace"), "", environment()).exit_code, 0);
  ASSERT_EQ(run_swarmdesign(traced("without.trace"), "", without_fma()).exit_code, 0);
  const std::string trace = read(scratch() / "with.trace");
  EXPECT_GT(trace.size(), 100000u);
  EXPECT_EQ(trace, read(scratch() / "without.trace"));
}

TEST_F(cross_cpu, ADesignEndsTheSameWithAndWithoutGlibcsFmaCode) {
  // The optimiser's sampling (truncated normals, log-scale parameters) goes through
  // core/math.hpp as well. Before it did, about 16 of these 1 100 runs (30 s each) scored
  // differently, though the best configuration happened to survive.
  const std::string mission = write_short_mission(scratch(), 30).string();
  auto args = [&](const std::string& out) {
    return std::vector<std::string>{"design", "--mission", mission, "--budget", "1100", "--seed", "3", "--threads", "2",
                                    "--out", (scratch() / out).string(), "--json", "--fsm", "--chocolate"};
  };
  const Outcome with = run_swarmdesign(args("with"), "", environment());
  const Outcome without = run_swarmdesign(args("without"), "", without_fma());
  ASSERT_EQ(with.exit_code, 0) << with.err;
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_EQ(design_outcome(with.out), design_outcome(without.out));
  EXPECT_EQ(experiment_log(scratch() / "with"), experiment_log(scratch() / "without"));
}

}  // namespace
}  // namespace sd::test
