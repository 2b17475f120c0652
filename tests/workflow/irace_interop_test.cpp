// `swarmdesign irace-export` end to end: the real irace 3.5 runs a small budget through the
// exported files and this swarmdesign's `evaluate`, and its best configuration is control
// software that `evaluate` accepts. Skipped when R's irace is not installed
// (scripts/setup.sh --tests installs r-cran-irace).
// Label interop, so the Release stage runs it and the sanitizer stages do not: under ASan it is
// 300 starts of the instrumented binary (100 s) parsing irace's strings, which irace's own
// samples already go through in-process there (design_IraceExport) and fuzz_config_string too.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
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
