// The product's inner loop: one 20-robot, 120-s AAC evaluation on one core.
// Reports ms per evaluation and robot-ticks per second.
#include <benchmark/benchmark.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "control/config_string.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"

namespace {

// Two-state FSMs from the calibration set (shared/calibration/argos-reference.csv).
const char* kAttractStop =
    "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 "
    "--s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";
const char* kExplorePhototaxis =
    "--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 "
    "--s1 12 --n1 1 --n1x0 0 --c1x0 12 --p1x0 1";

void run_aac(benchmark::State& state, const char* config) {
  const sd::Mission mission = sd::load_mission("aac");
  const sd::ControlSoftware software = sd::parse_control_software(std::string(config));
  sd::Simulation simulation(mission, software);
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(simulation.run(seed++));
  const double robot_ticks = static_cast<double>(mission.robots) * mission.ticks;
  state.counters["robot_ticks_per_s"] =
      benchmark::Counter(robot_ticks * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
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

void BM_AacDesignSample(benchmark::State& state) {
  const sd::Mission mission = sd::load_mission("aac");
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
  std::size_t next = 0;
  for (auto _ : state) {
    SampledRun& run = runs[next];
    benchmark::DoNotOptimize(run.simulation->run(run.seed));
    next = (next + 1) % runs.size();
  }
  const double robot_ticks = static_cast<double>(mission.robots) * mission.ticks;
  state.counters["robot_ticks_per_s"] =
      benchmark::Counter(robot_ticks * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_AacDesignSample)->Unit(benchmark::kMillisecond)->Iterations(8 * 25);
BENCHMARK(BM_AacAttractionStop)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacExplorationPhototaxis)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacColourFollowingCamera)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_AacMapleTree)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
