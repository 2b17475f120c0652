// The product's inner loop: one 20-robot, 120-s AAC evaluation on one core.
// Reports ms per evaluation and robot-ticks per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/assess_job.hpp"
#include "app/evaluation_job.hpp"
#include "control/config_string.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"
#include "missions/mission.hpp"
#include "reality/pseudo_reality.hpp"

namespace {

// Two-state FSMs from the calibration set (shared/calibration/argos-reference.csv).
const char* kAttractStop =
    "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 "
    "--s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";
const char* kExplorePhototaxis =
    "--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 "
    "--s1 12 --n1 1 --n1x0 0 --c1x0 12 --p1x0 1";

/// Robot-ticks per second, and nanoseconds per robot and tick (flat if the cost grows
/// linearly with the swarm). Every benchmark reports both: the CSV output needs the same
/// counters in every row.
void report_rates(benchmark::State& state, const sd::Mission& mission) {
  const double robot_ticks = static_cast<double>(mission.robots) * mission.ticks * static_cast<double>(state.iterations());
  state.counters["robot_ticks_per_s"] = benchmark::Counter(robot_ticks, benchmark::Counter::kIsRate);
  state.counters["ns_per_robot_tick"] =
      benchmark::Counter(robot_ticks / 1e9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void run_aac(benchmark::State& state, const char* config) {
  const sd::Mission mission = sd::load_mission("aac");
  const sd::ControlSoftware software = sd::parse_control_software(std::string(config));
  sd::Simulation simulation(mission, software);
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(simulation.run(seed++));
  report_rates(state, mission);
}

// The camera's cost: robots show yellow and follow yellow (TuttiFrutti GoToColor), on the
// same mission, compared with the attraction/stop FSM above.
const char* kColourFollowing =
    "--fsm-config --nstates 2 --s0 28 --vel0 1 --cle0 4 --clr0 4 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 "
    "--s1 21 --cle1 4 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";
// A Maple behaviour tree with the same modules as the attraction/stop FSM.
const char* kMapleTree =
    "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 44 --att01 5 --p01 0 "
    "--n1 0 --nchild1 2 --n10 6 --c10 41 --p10 0.1 --n11 5 --a11 41 --p11 0";

void BM_AacAttractionStop(benchmark::State& state) { run_aac(state, kAttractStop); }
void BM_AacColourFollowingCamera(benchmark::State& state) { run_aac(state, kColourFollowing); }
void BM_AacMapleTree(benchmark::State& state) { run_aac(state, kMapleTree); }
void BM_AacExplorationPhototaxis(benchmark::State& state) { run_aac(state, kExplorePhototaxis); }

// What a design spends its time on: the runs sampled from a real 200 000-run AAC design
// (bench/data/aac-design-sample.txt), each evaluated once per pass, in file order. The
// time is per evaluation; a fixed number of whole passes keeps the mix exact.
struct SampledRun {
  std::uint64_t seed;
  std::unique_ptr<sd::Simulation> simulation;
};

/// The design sample's runs, each in the design model (`spec` null) or in sample
/// 1 + (run index mod 20) of a pseudo-reality specification.
void run_design_sample(benchmark::State& state, const sd::PseudoRealitySpec* spec) {
  const sd::Mission mission = sd::load_mission("aac");
  std::vector<sd::RobotModel> models;
  for (std::uint64_t k = 1; spec && k <= 20; ++k) models.push_back(spec->sample(mission.robot, k));
  std::vector<SampledRun> runs;
  std::ifstream in(SWARMDESIGN_BENCH_DATA "/aac-design-sample.txt");
  if (!in) throw std::runtime_error("cannot read " SWARMDESIGN_BENCH_DATA "/aac-design-sample.txt");
  std::vector<std::pair<std::uint64_t, std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::uint64_t seed = 0;
    fields >> seed;
    std::string config;
    std::getline(fields, config);
    lines.emplace_back(seed, config);
  }
  for (const auto& [seed, config] : lines)
    runs.push_back({seed, std::make_unique<sd::Simulation>(mission, sd::parse_control_software(config))});
  std::size_t next = 0, count = 0;
  for (auto _ : state) {
    SampledRun& run = runs[next];
    const sd::RobotModel* model = models.empty() ? nullptr : &models[count++ % models.size()];
    benchmark::DoNotOptimize(run.simulation->run(run.seed, nullptr, model));
    next = (next + 1) % runs.size();
  }
  report_rates(state, mission);
}

void BM_AacDesignSample(benchmark::State& state) { run_design_sample(state, nullptr); }
// The same runs in pseudo-realities sampled around the design model (per-robot deviations,
// position noise on): what a robust design or an assessment pays per run.
void BM_AacDesignSampleInPseudoRealities(benchmark::State& state) {
  const auto spec = sd::builtin_pseudo_reality("sampled-around");
  run_design_sample(state, &*spec);
}

// Per run, an assessment (design model and 4 pseudo-reality samples, 4 seeds each: 20 runs)
// against the plain evaluation of 20 seeds, both through the application's jobs on one thread.
const char* kAssessed = "--fsm-config --nstates 2 --s0 4 --att0 3.5 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.8 --s1 0 --rwm1 50 --n1 1 --n1x0 0 --c1x0 1 --p1x0 0.5";

void BM_ScoreSeedsPerRun(benchmark::State& state) {
  const sd::Mission mission = sd::load_mission("aac");
  const sd::ControlSoftware software = sd::parse_control_software(std::string(kAssessed));
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = 1; s <= 20; ++s) seeds.push_back(s);
  sd::app::ScoreOptions one_thread;
  one_thread.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(sd::app::score_seeds(mission, software, seeds, one_thread));
  state.counters["ms_per_run"] = benchmark::Counter(20.0 * static_cast<double>(state.iterations()) / 1e3,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// Arg 0: in samples of sampled-around; arg 1: in a specification at the design values (the
/// same runs as plain evaluation, so the difference is the assessment's own cost).
void BM_AssessPerRun(benchmark::State& state) {
  const sd::Mission mission = sd::load_mission("aac");
  sd::app::AssessRequest request;
  request.software.push_back({"assessed", sd::parse_control_software(std::string(kAssessed))});
  if (state.range(0) == 0) {
    request.spec = *sd::builtin_pseudo_reality("sampled-around");
  } else {
    nlohmann::json knobs = nlohmann::json::object();
    for (const sd::RobotKnob& knob : sd::kRobotKnobs) knobs[std::string(knob.name)] = mission.robot.*(knob.member);
    request.spec = sd::parse_pseudo_reality(nlohmann::json{{"knobs", knobs}}.dump(), "design values");
  }
  request.samples = {1, 2, 3, 4};
  request.seeds = {1, 2, 3, 4};
  request.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(sd::app::assess(mission, request));
  state.counters["ms_per_run"] = benchmark::Counter(20.0 * static_cast<double>(state.iterations()) / 1e3,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}


// How the cost grows with the swarm: AAC with N robots in the arena scaled by sqrt(N / 20),
// so that the density (robots per square metre of arena, of spot, of start disc) stays
// AAC's. Every length of the mission file scales: walls, spots, start disc, the light's
// horizontal position (its height and the walls' height and thickness stay).
sd::Mission scaled_aac(int robots) {
  std::ifstream in(SWARMDESIGN_MISSIONS "/aac.json");
  if (!in) throw std::runtime_error("cannot read " SWARMDESIGN_MISSIONS "/aac.json");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json m = nlohmann::json::parse(text.str(), nullptr, true, /*ignore_comments=*/true);
  const double s = std::sqrt(robots / 20.0);
  auto scale_circle = [s](nlohmann::json& c) {
    c["center"][0] = c["center"][0].get<double>() * s;
    c["center"][1] = c["center"][1].get<double>() * s;
    c["radius"] = c["radius"].get<double>() * s;
  };
  m["robots"] = robots;
  auto& polygon = m["arena"]["walls"][0]["regular_polygon"];
  polygon["apothem"] = polygon["apothem"].get<double>() * s;
  polygon["length"] = polygon["length"].get<double>() * s;
  for (auto& patch : m["arena"]["floor"]["patches"]) scale_circle(patch["region"]["circle"]);
  for (auto& light : m["arena"]["lights"]) {
    light["position"][0] = light["position"][0].get<double>() * s;
    light["position"][1] = light["position"][1].get<double>() * s;
  }
  scale_circle(m["start"]["circle"]);
  scale_circle(m["objective"]["region"]["circle"]);
  return sd::parse_mission(m.dump(), "aac scaled to " + std::to_string(robots) + " robots");
}

enum class PairSearch { chosen, all_pairs };

void run_scaled(benchmark::State& state, const char* config, PairSearch search = PairSearch::chosen) {
  const sd::Mission mission = scaled_aac(static_cast<int>(state.range(0)));
  const sd::ControlSoftware software = sd::parse_control_software(std::string(config));
  sd::Simulation simulation(mission, software);
  if (search == PairSearch::all_pairs) simulation.use_neighbour_grid(false);
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(simulation.run(seed++));
  report_rates(state, mission);
}
void BM_ScalingAttractionStop(benchmark::State& state) { run_scaled(state, kAttractStop); }
void BM_ScalingExplorationPhototaxis(benchmark::State& state) { run_scaled(state, kExplorePhototaxis); }
void BM_ScalingColourFollowingCamera(benchmark::State& state) { run_scaled(state, kColourFollowing); }
// The same without the neighbour grid: what it saves, side by side.
void BM_ScalingAttractionStopAllPairs(benchmark::State& state) { run_scaled(state, kAttractStop, PairSearch::all_pairs); }
void BM_ScalingExplorationPhototaxisAllPairs(benchmark::State& state) {
  run_scaled(state, kExplorePhototaxis, PairSearch::all_pairs);
}
void BM_ScalingColourFollowingCameraAllPairs(benchmark::State& state) {
  run_scaled(state, kColourFollowing, PairSearch::all_pairs);
}

BENCHMARK(BM_AacDesignSample)->Unit(benchmark::kMillisecond)->Iterations(8 * 25);
BENCHMARK(BM_AacDesignSampleInPseudoRealities)->Unit(benchmark::kMillisecond)->Iterations(8 * 25);
// Real time: the runs are on the executor's worker, not the benchmark's thread.
BENCHMARK(BM_ScoreSeedsPerRun)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_AssessPerRun)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime()->Arg(0)->Arg(1);
BENCHMARK(BM_AacAttractionStop)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacExplorationPhototaxis)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacColourFollowingCamera)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacMapleTree)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK(BM_ScalingAttractionStop)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_ScalingExplorationPhototaxis)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_ScalingColourFollowingCamera)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_ScalingAttractionStopAllPairs)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_ScalingExplorationPhototaxisAllPairs)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);
BENCHMARK(BM_ScalingColourFollowingCameraAllPairs)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(20)->Arg(50)->Arg(100)->Arg(200);

}  // namespace

BENCHMARK_MAIN();
