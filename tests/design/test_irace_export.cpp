// Checks the export against the installed irace 3.5 (skipped when Rscript is absent).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "design/fsm_space.hpp"
#include "design/irace_export.hpp"

using namespace sd::design;
namespace fs = std::filesystem;

namespace {

bool have_rscript() { return std::system("Rscript -e 'library(irace)' >/dev/null 2>&1") == 0; }

std::string run(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  return out;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("sd_design_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(0, 1);
  return s;
}

}  // namespace

TEST(design_IraceExport, ParameterFileText) {
  const ParameterSpace s = build_fsm_space(chocolate_fsm_modules());
  const std::string text = irace_parameters_text(s);
  EXPECT_NE(text.find("ARCH\t\"--\"\tc\t(\"fsm-config\")\n"), std::string::npos);
  EXPECT_NE(text.find("NumStates\t\"--nstates \"\ti\t(1, 4)\n"), std::string::npos);
  EXPECT_NE(text.find("N1x2\t\"--n1x2 \"\ti\t(0, \"NumStates-2\")\t| NumConnections1 > 2\n"), std::string::npos);
  EXPECT_NE(text.find("B0x0\t\"--p0x0 \"\ti\t(1, 10)\t| C0x0 %in% c(\"13\", \"14\")\n"), std::string::npos);
  EXPECT_NE(text.find("NumConnections0\t\"--n0 \"\ti\t(1, 4)\t| NumStates > 1\n"), std::string::npos);
  const std::string runner = target_runner_text({"/opt/sd/swarmdesign", "aac", true});
  EXPECT_NE(runner.find("evaluate --mission \"$MISSION\" --seed \"$SEED\" \"$@\""), std::string::npos);
  EXPECT_NE(runner.find("MISSION='aac'"), std::string::npos);
}

TEST(design_IraceExport, TargetRunnerPrintsTheNegatedScore) {
  const fs::path dir = fresh_dir("runner");
  const fs::path fake_runner = dir / "fake-swarmdesign";
  {
    std::ofstream f(fake_runner);
    // Echoes its arguments to a file and prints a score like `swarmdesign evaluate`.
    f << "#!/bin/bash\necho \"$@\" > \"" << (dir / "args").string() << "\"\necho 'Simulating...' >&2\necho 'Score 12.5'\n";
  }
  fs::permissions(fake_runner, fs::perms::owner_all);
  const ParameterSpace s = build_fsm_space(chocolate_fsm_modules());
  write_irace_files(dir, s, {.max_experiments = 300, .seed = 4}, {"aac"}, {fake_runner.string(), "aac", true});
  const std::string out = run((dir / "target-runner").string() + " 7 1 12345 aac --fsm-config --nstates 1 --s0 11 2>&1");
  EXPECT_EQ(trim(out), "-12.5");
  std::ifstream args(dir / "args");
  std::string line;
  std::getline(args, line);
  EXPECT_EQ(line, "evaluate --mission aac --seed 12345 --fsm-config --nstates 1 --s0 11");
  const std::string scenario = irace_scenario_text({.max_experiments = 300, .seed = 4});
  EXPECT_NE(scenario.find("maxExperiments = 300"), std::string::npos);
  EXPECT_NE(scenario.find("digits = 2"), std::string::npos);
  fs::remove_all(dir);
}

TEST(design_IraceExport, TargetRunnerWorksForAnyExecutablePath) {
  // Every character the shell treats specially inside "${VAR:-default}" or in quotes. A path
  // pasted there unescaped was cut at the } (a binary under /tmp/x}y/ was looked for as
  // /tmp/xy/swarmdesign}) and would have run the $(...) below.
  const fs::path dir = fresh_dir("odd_path");
  const fs::path odd = dir / "x}y \"z\" $HOME $(touch pwned) `touch pwned2` back\\slash 'q' {a,b} *";
  fs::create_directories(odd);
  const fs::path fake = odd / "swarmdesign";
  {
    std::ofstream f(fake);
    f << "#!/bin/bash\necho \"$@\" > \"$(dirname \"$0\")/args\"\necho 'Score 3'\n";
  }
  fs::permissions(fake, fs::perms::owner_all);
  const ParameterSpace s = build_fsm_space(chocolate_fsm_modules());
  write_irace_files(dir, s, {.max_experiments = 300}, {"aac"}, {fake.string(), "aac", true});
  const std::string call = "cd " + dir.string() + " && env -u SWARMDESIGN ./target-runner 7 1 99 aac --fsm-config --nstates 1 2>&1";
  EXPECT_EQ(trim(run(call)), "-3");
  std::ifstream args(odd / "args");
  std::string line;
  std::getline(args, line);
  EXPECT_EQ(line, "evaluate --mission aac --seed 99 --fsm-config --nstates 1");
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_FALSE(fs::exists(dir / "pwned2"));

  // $SWARMDESIGN still overrides the default.
  const fs::path other = dir / "other-swarmdesign";
  {
    std::ofstream f(other);
    f << "#!/bin/bash\necho 'Score 5'\n";
  }
  fs::permissions(other, fs::perms::owner_all);
  EXPECT_EQ(trim(run("cd " + dir.string() + " && SWARMDESIGN=" + other.string() +
                     " ./target-runner 7 1 99 aac --fsm-config --nstates 1 2>&1")),
            "-5");
  fs::remove_all(dir);
}

TEST(design_IraceExport, IraceReadsTheParametersAndItsSamplesParseBack) {
  if (!have_rscript()) GTEST_SKIP() << "Rscript with irace not installed";
  const ParameterSpace s = build_fsm_space(chocolate_fsm_modules());
  const fs::path dir = fresh_dir("params");
  const fs::path file = dir / "parameters.txt";
  {
    std::ofstream f(file);
    f << irace_parameters_text(s);
  }
  std::ostringstream r;
  r << "Rscript -e 'suppressMessages(library(irace)); p <- readParameters(\"" << file.string()
    << "\", digits = 2); cat(\"NBVAR\", p$nbVariable, \"\\n\"); set.seed(1); "
       "x <- irace:::sampleUniform(p, 300, digits = 2); "
       "for (i in seq_len(nrow(x))) cat(\"CONF\", irace:::buildCommandLine(x[i, p$names], p$switches[p$names]), \"\\n\")' 2>&1";
  const std::string out = run(r.str());
  std::istringstream lines(out);
  std::string line;
  int configurations = 0;
  bool read_nbvar = false;
  std::vector<int> states(5, 0);
  while (std::getline(lines, line)) {
    if (line.rfind("NBVAR", 0) == 0) {
      EXPECT_EQ(trim(line.substr(5)), std::to_string(s.nb_variable()));
      read_nbvar = true;
    } else if (line.rfind("CONF", 0) == 0) {
      const std::string cmd = trim(line.substr(4));
      Configuration c;
      ASSERT_NO_THROW(c = s.parse(cmd)) << cmd;
      EXPECT_EQ(s.validate(c), "") << cmd;
      EXPECT_EQ(s.render(c), cmd);
      ++states[static_cast<std::size_t>(c.values[*s.index_of("NumStates")])];
      ++configurations;
    }
  }
  EXPECT_TRUE(read_nbvar) << out;
  EXPECT_EQ(configurations, 300) << out;
  for (int n = 1; n <= 4; ++n) EXPECT_GT(states[static_cast<std::size_t>(n)], 30);
  fs::remove_all(dir);
}

TEST(design_IraceExport, IraceRunsThroughTheExportedFiles) {
  if (!have_rscript()) GTEST_SKIP() << "Rscript with irace not installed";
  const fs::path dir = fresh_dir("run");
  const fs::path fake_runner = dir / "fake-swarmdesign";
  {
    // Stands in for `swarmdesign evaluate`: the score is the number of states plus seed noise,
    // so a maximising design must end with 4 states.
    std::ofstream f(fake_runner);
    f << "#!/bin/bash\n"
         "[ \"$1\" = evaluate ] && [ \"$2\" = --mission ] && [ \"$4\" = --seed ] || { echo bad call; exit 1; }\n"
         "shift 5\n"
         "[ \"$1\" = --fsm-config ] || { echo 'no --fsm-config'; exit 1; }\n"
         "while [ $# -gt 0 ]; do [ \"$1\" = --nstates ] && N=$2; shift; done\n"
         "echo \"Score $N.$((RANDOM % 10))\"\n";
  }
  fs::permissions(fake_runner, fs::perms::owner_all);
  const ParameterSpace s = build_fsm_space(chocolate_fsm_modules());
  IraceScenarioSpec scenario{.max_experiments = 150, .seed = 3};
  scenario.nb_iterations = 2;
  scenario.min_nb_survival = 2;
  write_irace_files(dir, s, scenario, {"aac"}, {fake_runner.string(), "aac", true});
  const std::string out =
      run("cd " + dir.string() + " && Rscript -e 'irace::irace.cmdline(c(\"--scenario\", \"scenario.txt\"))' 2>&1");
  const auto at = out.find("# Best configurations as commandlines");
  ASSERT_NE(at, std::string::npos) << out;
  std::istringstream lines(out.substr(at));
  std::string line;
  std::getline(lines, line);
  ASSERT_TRUE(std::getline(lines, line)) << out;
  const std::string cmd = line.substr(line.find("--"));
  Configuration best;
  ASSERT_NO_THROW(best = s.parse(cmd)) << cmd;
  EXPECT_EQ(best.values[*s.index_of("NumStates")], 4) << cmd;
  fs::remove_all(dir);
}
