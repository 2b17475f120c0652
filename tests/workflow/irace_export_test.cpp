// `swarmdesign irace-export`: the four files it writes, and the flags and budgets it refuses.
// The real irace running through them is irace_interop_test.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

class irace_export : public WorkflowTest {};

TEST_F(irace_export, WritesTheFourFilesAndRefusesBadFlags) {
  const auto dir = scratch() / "export";
  const std::string out = run_ok({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "20000",
                                  "--out", dir.string()});
  EXPECT_NE(out.find("irace.cmdline"), std::string::npos) << out;
  for (const char* file : {"parameters.txt", "scenario.txt", "instances.txt", "target-runner"})
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  struct stat info{};
  ASSERT_EQ(::stat((dir / "target-runner").c_str(), &info), 0);
  EXPECT_TRUE(info.st_mode & S_IXUSR);
  std::ifstream scenario(dir / "scenario.txt");
  const std::string text((std::istreambuf_iterator<char>(scenario)), {});
  EXPECT_NE(text.find("maxExperiments = 20000"), std::string::npos) << text;

  expect_error(run({"irace-export", "--mission", "nope", "--out", dir.string()}), 2, "unknown mission");
  expect_error(run({"irace-export", "--mission", "aac", "--budget", "0", "--out", dir.string()}), 2, "positive integer");
}

// irace 3.5 refuses maxExperiments below its computeMinimumBudget (1008 for FSM+Chocolate,
// 126 with nbIterations = 2): the export says so in design's words and writes nothing.
TEST_F(irace_export, RefusesABudgetBelowIracesMinimumLikeDesignDoes) {
  const auto dir = scratch() / "export";
  const auto exported = run({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "300", "--out",
                             dir.string()});
  expect_error(exported, 2, "a budget of 300 simulation runs is below the minimum of 1008");
  EXPECT_FALSE(std::filesystem::exists(dir));
  const auto designed = run({"design", "--mission", "aac", "--fsm", "--chocolate", "--budget", "300", "--out",
                             (scratch() / "design").string()});
  EXPECT_EQ(exported.err, designed.err);

  expect_error(run({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "1007", "--out",
                    dir.string()}),
               2, "below the minimum of 1008");
  EXPECT_FALSE(std::filesystem::exists(dir));
  run_ok({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "1008", "--out", dir.string()});

  // The minimum counts the iterations written into the scenario, as irace does.
  const auto two = scratch() / "two-iterations";
  expect_error(run({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "125", "--iterations", "2",
                    "--out", two.string()}),
               2, "below the minimum of 126 that Iterated F-Race needs for this design space with 2 iterations");
  EXPECT_FALSE(std::filesystem::exists(two));
  run_ok({"irace-export", "--mission", "aac", "--fsm", "--chocolate", "--budget", "126", "--iterations", "2", "--out",
          two.string()});
}

}  // namespace
}  // namespace sd::test
