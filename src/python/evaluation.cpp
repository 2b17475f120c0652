// Evaluations and traces from Python: app::score_seeds (what `evaluate --seeds` runs) and
// app::observed_run (what `evaluate --trace` runs), on a thread of their own with the GIL
// released and stopped by Ctrl-C (interruptible.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "app/cancel_token.hpp"
#include "app/errors.hpp"
#include "app/evaluation_job.hpp"
#include "core/executor.hpp"
#include "evaluation/simulation.hpp"
#include "python/bindings.hpp"
#include "python/interruptible.hpp"

namespace sd::python {

namespace py = pybind11;

namespace {

/// What `evaluate --seeds A-B` accepts at most, for any list of seeds.
constexpr std::size_t kMaxSeeds = 1'000'000;
/// Each worker is a thread with its own simulation: a typo must not exhaust the machine.
constexpr int kMaxThreads = 1024;

py::array_t<double> evaluate(const std::shared_ptr<Mission>& mission, const std::shared_ptr<ControlSoftware>& software,
                             const std::vector<std::uint64_t>& seeds, int threads, const py::object& progress) {
  if (seeds.empty()) throw app::InvalidRequest("seeds: expected at least one seed");
  if (seeds.size() > kMaxSeeds) throw app::InvalidRequest("seeds: at most 1,000,000 seeds");
  if (threads < 0) throw app::InvalidRequest("threads: expected a non-negative integer (0: all cores)");
  if (threads > kMaxThreads) throw app::InvalidRequest("threads: at most " + std::to_string(kMaxThreads));
  std::vector<double> scores;
  app::CancelToken token;
  std::atomic<std::size_t> done{0};
  std::size_t reported = 0;
  app::ScoreOptions options;
  options.threads = threads;
  // Scores never depend on the batches; these give Ctrl-C and progress a point between two.
  options.progress = [&](std::size_t runs_done, std::size_t) {
    done.store(runs_done);
    if (token.cancelled()) throw JobCancelled{};
  };
  run_interruptibly([&] { scores = app::score_seeds(*mission, *software, seeds, options); }, [&] { token.cancel(); },
                    [&] {
                      const std::size_t now = done.load();
                      if (progress.is_none() || now == reported) return;
                      reported = now;
                      progress(now, seeds.size());
                    });
  py::array_t<double> result(static_cast<py::ssize_t>(scores.size()));
  std::copy(scores.begin(), scores.end(), result.mutable_data());
  return result;
}

// ---- traces -----------------------------------------------------------------------------

/// Every tick of one run, as `evaluate --trace` writes it (evaluation/trace_writer.cpp: the
/// same columns and the same tick semantics), kept as numbers: row k holds the pose after the
/// physics of tick k, the wheel speeds applied during it and the LED colour shown during it
/// (both commanded at tick k-1), the FSM state after the transition check (or the tree's
/// action counted depth-first), the module that ran (its two-digit id; the CSV prints id % 10)
/// and the floor its conditions read. Tick 0 is the placement (state, module -1, ground NaN).
class TraceRecorder final : public TickObserver {
 public:
  TraceRecorder(const Mission& mission, const app::CancelToken& token)
      : token_(token), ticks_(static_cast<std::size_t>(mission.ticks) + 1), robots_(static_cast<std::size_t>(mission.robots)) {
    const std::size_t cells = ticks_ * robots_;
    x.assign(cells, 0.0);
    y.assign(cells, 0.0);
    yaw.assign(cells, 0.0);
    v_left.assign(cells, 0.0);
    v_right.assign(cells, 0.0);
    ground.assign(cells, std::numeric_limits<double>::quiet_NaN());
    state.assign(cells, -1);
    module.assign(cells, -1);
    led.assign(cells, 0);
    objective.assign(ticks_, 0.0);
  }

  void on_tick(const Simulation& sim) override {
    if (token_.cancelled()) throw JobCancelled{};
    const SwarmState& s = sim.swarm();
    if (sim.tick() == 0) start(sim);
    const auto tick = static_cast<std::size_t>(sim.tick());
    if (tick >= ticks_ || static_cast<std::size_t>(s.size) != robots_) throw std::runtime_error("trace: unexpected tick or swarm size");
    for (std::size_t r = 0; r < robots_; ++r) {
      const std::size_t cell = tick * robots_ + r;
      const int i = static_cast<int>(r);
      x[cell] = s.position[r].x;
      y[cell] = s.position[r].y;
      yaw[cell] = s.yaw[r];
      v_left[cell] = previous_left_[r];
      v_right[cell] = previous_right_[r];
      led[cell] = previous_led_[r];
      if (tick > 0) {
        const auto [ran_state, ran_module] = what_ran(sim, i);
        state[cell] = ran_state;
        module[cell] = ran_module;
        const ReferenceModel& rm = sim.reference_model(i);
        ground[cell] = demiurge_floor_ ? rm.ground_demiurge : rm.ground;
      }
      previous_state_[r] = sim.fsm_state(i);
      previous_left_[r] = s.wheel_left[r];
      previous_right_[r] = s.wheel_right[r];
      previous_led_[r] = s.led[r];
    }
    objective[tick] = sim.score();
  }

  std::size_t ticks() const { return ticks_; }
  std::size_t robots() const { return robots_; }

  std::vector<double> x, y, yaw, v_left, v_right, ground, objective;
  std::vector<std::int32_t> state, module;
  std::vector<std::uint32_t> led;

 private:
  static void number_leaves(const BehaviourTree& bt, int node, int& next, std::vector<int>& numbers) {
    const BtNode& n = bt.nodes[static_cast<std::size_t>(node)];
    if (n.type == BtNodeType::Action) numbers[static_cast<std::size_t>(node)] = next++;
    for (const int child : n.children) number_leaves(bt, child, next, numbers);
  }

  void start(const Simulation& sim) {
    const ControlSoftware& software = sim.software();
    leaf_number_.assign(software.bt.nodes.size(), -1);
    int next = 0;
    if (!software.bt.nodes.empty()) number_leaves(software.bt, 0, next, leaf_number_);
    previous_state_.assign(robots_, 0);
    previous_left_.assign(robots_, 0.0);
    previous_right_.assign(robots_, 0.0);
    previous_led_.assign(robots_, 0);
    const auto demiurge = [](const ModuleInstance& m) { return m.id / 10 == 3 || m.id / 10 == 5; };
    demiurge_floor_ = software.architecture == Architecture::NeuralNetwork;
    for (const FsmState& s : software.fsm.states) demiurge_floor_ = demiurge_floor_ || demiurge(s.behaviour);
    for (const BtNode& n : software.bt.nodes)
      demiurge_floor_ = demiurge_floor_ || (n.type == BtNodeType::Action && demiurge(n.module));
  }

  std::pair<int, int> what_ran(const Simulation& sim, int robot) const {
    const ControlSoftware& software = sim.software();
    const int current = sim.fsm_state(robot);
    switch (software.architecture) {
      case Architecture::Fsm: {
        const int before = previous_state_[static_cast<std::size_t>(robot)];
        return {current, software.fsm.states[static_cast<std::size_t>(before)].behaviour.id};
      }
      case Architecture::BehaviourTree:
        if (current < 0) return {-1, -1};
        return {leaf_number_[static_cast<std::size_t>(current)], software.bt.nodes[static_cast<std::size_t>(current)].module.id};
      case Architecture::NeuralNetwork: break;
    }
    return {-1, -1};
  }

  const app::CancelToken& token_;
  std::size_t ticks_, robots_;
  std::vector<int> leaf_number_, previous_state_;
  std::vector<double> previous_left_, previous_right_;
  std::vector<std::uint32_t> previous_led_;
  bool demiurge_floor_ = false;
};

template <class T>
py::array_t<T> matrix(const std::vector<T>& values, std::size_t rows, std::size_t columns) {
  py::array_t<T> array({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::dict trace(const std::shared_ptr<Mission>& mission, const std::shared_ptr<ControlSoftware>& software,
               std::uint64_t seed) {
  app::CancelToken token;
  auto recorder = std::make_unique<TraceRecorder>(*mission, token);
  double score = 0.0;
  run_interruptibly([&] { score = app::observed_run(*mission, *software, seed, *recorder); }, [&] { token.cancel(); });
  const std::size_t ticks = recorder->ticks(), robots = recorder->robots();
  py::dict out;
  out["score"] = score;
  out["x"] = matrix(recorder->x, ticks, robots);
  out["y"] = matrix(recorder->y, ticks, robots);
  out["yaw"] = matrix(recorder->yaw, ticks, robots);
  out["v_left"] = matrix(recorder->v_left, ticks, robots);
  out["v_right"] = matrix(recorder->v_right, ticks, robots);
  out["ground"] = matrix(recorder->ground, ticks, robots);
  out["state"] = matrix(recorder->state, ticks, robots);
  out["module"] = matrix(recorder->module, ticks, robots);
  out["led"] = matrix(recorder->led, ticks, robots);
  out["objective"] = matrix(recorder->objective, ticks, 1).attr("reshape")(static_cast<py::ssize_t>(ticks));
  return out;
}

}  // namespace

void bind_evaluation(py::module_& m) {
  m.def("evaluate", &evaluate, py::arg("mission"), py::arg("software"), py::arg("seeds"), py::arg("threads") = 0,
        py::arg("progress") = py::none(),
        "Scores per seed, in seed order, the bits `swarmdesign evaluate` prints (app::score_seeds).");
  m.def("pool_threads", [] { return Executor::shared().size(); },
        "Threads in the process's worker pool now (a child forked after they started has none).");
  m.def("trace", &trace, py::arg("mission"), py::arg("software"), py::arg("seed"),
        "One run recorded tick by tick (the run and score of `evaluate --trace`), as arrays.");
}

}  // namespace sd::python
