// `swarmdesign evostick` end to end: the baseline on a mission (text, --json, threads), a
// module's document, the network it prints evaluated by `evaluate`, and one-line errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "workflow/swarmdesign_process.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

using test::run_swarmdesign;

test::Outcome run(const std::string& line) {
  std::vector<std::string> args;
  std::istringstream in(line);
  for (std::string a; in >> a;) args.push_back(a);
  return run_swarmdesign(args, "", {});
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

const std::string kSmallBaseline = "evostick --mission aac --budget 65 --population 6 --evaluations 2 --elites 2 --seed 4";

TEST(EvoStickCli, BaselinePrintsTheNetworkItsMeanAndTheRunsWhateverTheThreads) {
  const auto one = run(kSmallBaseline + " --threads 1");
  const auto two = run(kSmallBaseline + " --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
  const auto lines = lines_of(one.out);
  ASSERT_EQ(lines.size(), 4u) << one.out;
  EXPECT_EQ(lines[0].rfind("--nn-config --w0x0 ", 0), 0u);
  EXPECT_EQ(lines[1].rfind("Mean ", 0), 0u);
  EXPECT_EQ(lines[2], "Runs 60") << "65 runs pay for 5 generations of 6 x 2";
  EXPECT_EQ(lines[3], "Generations 5");

  // The printed network is control software `evaluate` runs, inline or from a file.
  const auto evaluated = run("evaluate --mission aac --seed 2 " + lines[0]);
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
  EXPECT_EQ(evaluated.out.rfind("Score ", 0), 0u);
}

TEST(EvoStickCli, BaselineJsonAgreesWithText) {
  const auto text = run(kSmallBaseline);
  const auto json = run(kSmallBaseline + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  const auto lines = lines_of(text.out);
  EXPECT_EQ(doc["control_software"], lines[0]);
  EXPECT_EQ(doc["mission"], "aac");
  EXPECT_EQ(doc["direction"], "maximize");
  EXPECT_EQ(doc["budget"], 65);
  EXPECT_EQ(doc["runs"], 60);
  EXPECT_EQ(doc["settings"]["generations"], 5);
  EXPECT_EQ(doc["settings"]["seed"], 4);
  ASSERT_EQ(doc["history"].size(), 5u);
  EXPECT_EQ(doc["history"].back()["best_mean"], doc["mean"]);
  EXPECT_EQ(doc["history"].back()["best_digest"], doc["weights_digest"]);
  EXPECT_EQ(doc["weights"]["left"].size(), 25u);
  EXPECT_EQ(doc["weights"]["right"].size(), 25u);
}

TEST(EvoStickCli, ModuleOutputFileIsTheJsonDocument) {
  const auto dir = std::filesystem::temp_directory_path() / ("sd_evostick_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "stop.json").string();
  const std::string command = "evostick --module stop --generations 2 --population 4 --evaluations 1 --elites 1";
  const auto written = run(command + " --output " + file);
  const auto json = run(command + " --json");
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_NE(written.out.find("Written to " + file), std::string::npos);
  EXPECT_NE(written.out.find("Measure stillness (maximised)"), std::string::npos);
  std::ifstream in(file);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), json.out);
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["module"], 51);
  EXPECT_EQ(doc["name"], "stop");
  EXPECT_EQ(doc["produced_by"],
            "swarmdesign evostick --module stop --seed 1 --generations 2 --population 4 --evaluations 1 --elites 1");
  EXPECT_EQ(doc["training"]["measure"], "stillness");
  EXPECT_EQ(doc["training"]["arena"], "data/arlequin/training/cues.json");
  EXPECT_EQ(doc["runs"], 8);
  std::filesystem::remove_all(dir);
}

TEST(EvoStickCli, ProgressGoesToTheTerminal) {
  const auto shown = test::run_swarmdesign_on_terminal(
      {"evostick", "--module", "stop", "--generations", "2", "--population", "4", "--evaluations", "1", "--elites", "1"}, {},
      {});
  ASSERT_EQ(shown.exit_code, 0) << shown.out;
  EXPECT_NE(shown.out.find("generation 2/2: best mean"), std::string::npos) << shown.out;
  const auto piped = run("evostick --module stop --generations 2 --population 4 --evaluations 1 --elites 1");
  EXPECT_EQ(piped.err, "");
}

TEST(EvoStickCli, MisuseIsAOneLineErrorWithExitStatusTwo) {
  const std::pair<std::string, std::string> cases[] = {
      {"evostick --module dance", "unknown module 'dance' (one of exploration, stop, phototaxis, antiphototaxis, "
                                  "attraction, repulsion)"},
      {"evostick --mission aac", "--mission needs a budget"},
      {"evostick --mission aac --budget 999", "does not pay for one generation (1000 runs"},
      {"evostick --mission aac --budget 5000 --elites 100", "elites must be between 1 and population - 1"},
      {"evostick --mission nowhere --budget 5000", "unknown mission 'nowhere'"},
      {"evostick --seed 3", "give --module NAME, --mission M or --resume FILE"},
      {"evostick --module stop --mission aac", "excludes"},
      {"evostick --module stop --fsm-config --nstates 1 --s0 10 --rwm0 5", "evostick takes no control software"},
  };
  for (const auto& [command, message] : cases) {
    const auto r = run(command);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find(message), std::string::npos) << command << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << "\n" << r.err;
  }
}

TEST(EvoStickCli, AKilledEvolutionResumesFromItsStateFileAndEndsAsAnUninterruptedOne) {
  const auto dir = std::filesystem::temp_directory_path() / ("evostick-state-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string state = (dir / "run.evostick").string();
  const std::string settings = "evostick --mission aac --generations 8 --population 6 --evaluations 2 --elites 2 --seed 5";
  const auto whole = run(settings + " --json");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  auto saved_generation = [&] {
    std::ifstream in(state);
    const auto doc = nlohmann::json::parse(in, nullptr, false);
    return doc.is_discarded() ? -1 : doc.value("generation", -1);
  };
  std::vector<std::string> args;
  std::istringstream words(settings + " --json --state " + state);
  for (std::string w; words >> w;) args.push_back(w);
  // The evolution SIGKILLs itself right after generation 4 is in its state file.
  const int pid = test::start_swarmdesign(args, {{{"SWARMDESIGN_KILL_AT_CHECKPOINT", "4"}}, {}},
                                          (dir / "out").string(), (dir / "err").string());
  EXPECT_EQ(test::wait_swarmdesign(pid), -1) << "the evolution ended before it could be killed";
  const int killed_at = saved_generation();
  ASSERT_EQ(killed_at, 4);

  const auto resumed = run("evostick --resume " + state + " --json");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(resumed.out, whole.out) << "killed after generation " << killed_at;
  EXPECT_EQ(saved_generation(), 7) << "the state is kept on while resuming";

  // A state file is never silently overwritten, nor resumed with other settings.
  const auto again = run(settings + " --state " + state);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("already holds an evolution; continue it with --resume"), std::string::npos) << again.err;
  const auto changed = run("evostick --resume " + state + " --seed 6");
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_NE(changed.err.find("--seed cannot change it"), std::string::npos) << changed.err;
  std::ofstream(dir / "damaged.evostick") << "{\"format\": \"swarmdesign-evostick-state\", \"version\": 1, \"mission\"";
  const auto damaged = run("evostick --resume " + (dir / "damaged.evostick").string());
  EXPECT_EQ(damaged.exit_code, 1);
  EXPECT_NE(damaged.err.find("not an EvoStick state file"), std::string::npos) << damaged.err;
  EXPECT_EQ(std::count(damaged.err.begin(), damaged.err.end(), '\n'), 1) << damaged.err;
  // Nor by a build whose runs score differently.
  auto older = nlohmann::json::parse(std::ifstream(state));
  older["results_version"] = 1;
  std::ofstream(dir / "older.evostick") << older.dump();
  const auto refused = run("evostick --resume " + (dir / "older.evostick").string());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("(results version 1, this one "), std::string::npos) << refused.err;
  std::filesystem::remove_all(dir);
}

TEST(EvoStickCli, AnEvolutionWhoseMissionFileWasEditedIsNotResumed) {
  const auto dir = std::filesystem::temp_directory_path() / ("evostick-edited-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::stringstream aac;
  aac << std::ifstream(std::string(::sd::test::source_dir()) + "/missions/aac.json").rdbuf();
  const auto mission = dir / "mine.json";
  std::ofstream(mission) << aac.str();
  const std::string state = (dir / "mine.evostick").string();
  const auto first = run("evostick --mission " + mission.string() +
                         " --generations 3 --population 4 --evaluations 1 --elites 1 --state " + state);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  std::ofstream(mission) << std::regex_replace(aac.str(), std::regex("\"duration\": *[0-9.]+"), "\"duration\": 60");
  const auto refused = run("evostick --resume " + state);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("has changed since the evolution"), std::string::npos) << refused.err;
  std::filesystem::remove_all(dir);
}

TEST(EvoStickCli, EvaluateRunsArlequinModulesInAnFsmAndATree) {
  const auto fsm = run(
      "evaluate --mission aac --seeds 1-3 --fsm-config --nstates 2 --s0 50 --n0 1 --n0x0 0 --c0x0 50 --p0x0 0.5 "
      "--s1 52 --n1 1 --n1x0 0 --c1x0 55 --p1x0 0.1");
  ASSERT_EQ(fsm.exit_code, 0) << fsm.err;
  EXPECT_NE(fsm.out.find("Mean "), std::string::npos);
  const auto tree = run(
      "evaluate --mission aac --seed 1 --bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 50 "
      "--p00 0.9 --n01 5 --a01 54 --p01 0");
  ASSERT_EQ(tree.exit_code, 0) << tree.err;
  EXPECT_EQ(tree.out.rfind("Score ", 0), 0u);
  const auto legacy = run("evaluate --mission aac --seed 1 --legacy-flavour arlequin --fsm-config --nstates 1 --s0 2");
  ASSERT_EQ(legacy.exit_code, 0) << legacy.err;
}

}  // namespace
}  // namespace sd
