// `swarmdesign irace-export` end to end: the real irace 3.5 runs a small budget through the
// exported files and this swarmdesign's `evaluate`, and its best configuration is control
// software that `evaluate` accepts. Skipped when R's irace is not installed
// (scripts/setup.sh installs r-cran-irace).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

bool have_irace() { return std::system("Rscript -e 'library(irace)' >/dev/null 2>&1") == 0; }

std::string shell_output(const std::string& command) {
  std::string out;
  if (FILE* p = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, p)) out += buffer;
    ::pclose(p);
  }
  return out;
}

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

TEST_F(irace_export, TheRealIraceFindsControlSoftwareThroughTheExport) {
  if (!have_irace()) GTEST_SKIP() << "Rscript with the irace package is not installed";
  const auto mission = write_short_mission(scratch(), 5);
  const auto dir = scratch() / "irace";
  run_ok({"irace-export", "--mission", mission.string(), "--fsm", "--chocolate", "--budget", "300", "--seed", "1",
          "--iterations", "2", "--out",
          dir.string()});
  // target-runner runs the binary under test; SWARMDESIGN_HOME stays in the scratch folder.
  const std::string log = shell_output("cd '" + dir.string() + "' && SWARMDESIGN_HOME='" + home().string() +
                                       "' Rscript -e 'irace::irace.cmdline(c(\"--scenario\", \"scenario.txt\"))' 2>&1");
  const auto at = log.find("# Best configurations as commandlines");
  ASSERT_NE(at, std::string::npos) << log;
  std::istringstream lines(log.substr(at));
  std::string line;
  std::getline(lines, line);
  ASSERT_TRUE(std::getline(lines, line)) << log;
  ASSERT_NE(line.find("--fsm-config"), std::string::npos) << line;
  std::vector<std::string> args{"evaluate", "--mission", mission.string(), "--seed", "3"};
  std::istringstream tokens(line.substr(line.find("--fsm-config")));
  for (std::string token; tokens >> token;) args.push_back(token);
  EXPECT_NE(run_ok(args).find("Score "), std::string::npos);
}

}  // namespace
}  // namespace sd::test
