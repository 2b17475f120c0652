// The swarmdesign binary end to end, as a user (or irace's target-runner) runs it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

#include "run_cli.hpp"
#include "test_paths.hpp"

namespace {

using Result = sd::test::CliResult;
Result run(const std::string& args) { return sd::test::run_cli(args); }

int count_lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

const std::string kRandomWalk = " --fsm-config --nstates 1 --s0 10 --rwm0 50";

TEST(Cli, EvaluatePrintsAScorePerSeedThenMeanAndMedianWhateverTheThreads) {
  const Result one = run("evaluate --mission aac --seeds 1-20 --threads 1" + kRandomWalk);
  const Result two = run("evaluate --mission aac --seeds 1-20 --threads 2" + kRandomWalk);
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(count_lines_starting(one.out, "Score "), 20);
  EXPECT_EQ(count_lines_starting(one.out, "Mean "), 1);
  EXPECT_EQ(count_lines_starting(one.out, "Median "), 1);
  EXPECT_EQ(one.out, two.out);
}

TEST(Cli, EvaluateJsonAgreesWithText) {
  const Result text = run("evaluate --mission aac --seed 3" + kRandomWalk);
  const Result json = run("evaluate --mission aac --seed 3 --json" + kRandomWalk);
  ASSERT_EQ(json.status, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["runs"][0]["seed"], 3);
  EXPECT_EQ(text.out, "Score " + std::to_string(doc["runs"][0]["score"].get<int>()) + "\n");
  EXPECT_EQ(doc["control_software"], "--fsm-config --nstates 1 --s0 10 --rwm0 50");
}

TEST(Cli, ArlequinModulesPicksTheSetAndABadOneIsOneLine) {
  const std::string attraction = " --seeds 1-3 --fsm-config --nstates 1 --s0 54";
  const Result shipped = run("evaluate --mission aac" + attraction);
  const Result named = run("evaluate --mission aac --arlequin-modules swarmdesign" + attraction);
  const Result demiurge = run("evaluate --mission aac --arlequin-modules demiurge" + attraction);
  const Result folder =
      run("evaluate --mission aac --arlequin-modules " + std::string(::sd::test::source_dir()) + "/data/arlequin-demiurge" + attraction);
  ASSERT_EQ(demiurge.status, 0) << demiurge.err;
  EXPECT_EQ(named.out, shipped.out);
  EXPECT_NE(demiurge.out, shipped.out);
  EXPECT_EQ(folder.out, demiurge.out);
  const Result bad = run("evaluate --mission aac --arlequin-modules demiurg" + attraction);
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "swarmdesign: error: arlequin_modules: Arlequin module set 'demiurg' is neither swarmdesign, demiurge "
                     "nor a folder of the six weight documents\n");
}

TEST(Cli, LegacyOneDigitStringsRunAsChocolate) {
  const Result legacy = run("evaluate --mission aac --seed 2 --fsm-config --nstates 1 --s0 0 --rwm0 50");
  const Result modern = run("evaluate --mission aac --seed 2" + kRandomWalk);
  ASSERT_EQ(legacy.status, 0) << legacy.err;
  EXPECT_EQ(legacy.out, modern.out);
}

TEST(Cli, TraceHasARowPerRobotPerTickAndEndsOnTheScore) {
  const auto path = std::filesystem::temp_directory_path() / "sd_trace_test.csv";
  const Result r = run("evaluate --mission aac --seed 4 --trace " + path.string() + kRandomWalk);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(path);
  std::string line, last;
  int rows = 0;
  std::getline(in, line);
  EXPECT_EQ(line, "tick,robot,x,y,yaw,v_left,v_right,state,behaviour,ground,led,objective");
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 1201 * 20);
  EXPECT_EQ(last.rfind("1200,epuck19,", 0), 0u);
  const std::string score = r.out.substr(6, r.out.size() - 7);
  EXPECT_EQ(last.substr(last.rfind(',') + 1), score);
  std::filesystem::remove(path);
}

TEST(Cli, RenderWritesAnSvgFrameEveryNTicksWithEveryRobotAndTheSameScore) {
  const auto folder = std::filesystem::temp_directory_path() / "sd_render_test";
  std::filesystem::remove_all(folder);
  const Result plain = run("evaluate --mission aac --seed 4" + kRandomWalk);
  const Result r = run("evaluate --mission aac --seed 4 --render " + folder.string() + " --render-every 100" + kRandomWalk);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, plain.out);  // drawing the run does not change it
  int frames = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) frames += entry.path().extension() == ".svg";
  EXPECT_EQ(frames, 13);  // ticks 0, 100, ..., 1200
  std::ifstream in(folder / "frame-01200.svg");
  std::stringstream svg;
  svg << in.rdbuf();
  const std::string text = svg.str();
  const std::string robots = text.substr(text.find("class=\"robots\""));
  int circles = 0;
  for (std::size_t at = robots.find("<circle"); at != std::string::npos; at = robots.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 20);
  EXPECT_NE(text.find("tick 1200 / 1200"), std::string::npos);
  EXPECT_EQ(run("evaluate --mission aac --seeds 1-2 --render " + folder.string() + kRandomWalk).status, 2);
  std::filesystem::remove_all(folder);
}

TEST(Cli, MalformedInputGetsOneLineErrorsAndExitStatusTwo) {
  struct Case {
    std::string args, needle;
  };
  const Case cases[] = {
      {"evaluate --mission aac --fsm-config --nstates 1 --s0 17", "unknown behaviour id 17"},
      {"evaluate --mission aac --fsm-config --nstates 2 --s0 10 --rwm0 5 --s1 11 --n1 1 --n1x0 1 --c1x0 15 --p1x0 0.5",
       "--n1x0 1"},
      {"evaluate --mission aac --fsm-config --nstates 1 --s0 14 --att0 9", "--att0 9"},
      {"evaluate --mission aac --fsm-config --nstates 1 --s0 11 --rwm0 3", "--rwm0 3"},
      {"evaluate --mission atlantis" + kRandomWalk, "unknown mission 'atlantis'"},
      {"evaluate --mission aac --seeds 5-2" + kRandomWalk, "seeds '5-2': the range is empty"},
      {"evaluate --mission aac", "no control software"},
      {"evaluate" + kRandomWalk, "--mission is required"},
      {"frobnicate", "frobnicate"},
  };
  for (const Case& c : cases) {
    const Result r = run(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(r.err.rfind("swarmdesign: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << " -> " << r.err;
  }
}

TEST(Cli, MissionsListAndShowWithADrawing) {
  const Result list = run("missions --json");
  ASSERT_EQ(list.status, 0) << list.err;
  const auto doc = nlohmann::json::parse(list.out);
  ASSERT_FALSE(doc.empty());
  EXPECT_EQ(doc[0]["name"], "aac");
  const auto svg = std::filesystem::temp_directory_path() / "sd_aac_test.svg";
  const Result show = run("mission show aac --svg " + svg.string());
  ASSERT_EQ(show.status, 0) << show.err;
  EXPECT_NE(show.out.find("Aggregation with ambient cues"), std::string::npos);
  std::ifstream in(svg);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string content = buffer.str();
  EXPECT_EQ(content.rfind("<svg", 0), 0u);
  // svg, title and its end, the outside, the y-up group, the arena's clip path (3 tags), the
  // floor group with its background, 2 patches and the objective's zone and its end, the start
  // region, 12 walls, the light, the group's end, the svg's end.
  EXPECT_EQ(std::count(content.begin(), content.end(), '<'), 1 + 2 + 1 + 1 + 3 + 1 + 1 + 2 + 1 + 1 + 1 + 12 + 1 + 1 + 1) << content;
  std::filesystem::remove(svg);
}

TEST(Cli, EveryCommandHasHelp) {
  for (const char* command : {"missions", "mission show", "evaluate", "show-config"}) {
    const Result r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << command;
  }
}

TEST(Cli, ShowConfigPrintsStatesAndDot) {
  const std::string fsm =
      " --fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 --s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";
  const Result text = run("show-config" + fsm);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("state 0: Attraction[14](att=5)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("-> state 1 when BlackFloor[10](p=1)"), std::string::npos) << text.out;
  const Result dot = run("show-config --dot" + fsm);
  EXPECT_NE(dot.out.find("s0 -> s1"), std::string::npos);
  EXPECT_NE(dot.out.find("s1 -> s0"), std::string::npos);
}

}  // namespace
