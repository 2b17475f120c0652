#include "evaluation/trace_writer.hpp"

#include <cstdio>

namespace sd {

namespace {

/// The set-4 traces' LED names for TuttiFrutti's pure colours, else #rrggbb.
void led_name(std::uint32_t rgb, char (&name)[16]) {
  struct Named { std::uint32_t rgb; const char* name; };
  static constexpr Named kNames[] = {{0x000000, "off"},     {0x00ff00, "green"},   {0x0000ff, "blue"},
                                     {0xff0000, "red"},     {0xffff00, "yellow"},  {0xff00ff, "magenta"},
                                     {0x00ffff, "cyan"}};
  for (const Named& n : kNames)
    if (n.rgb == rgb) { std::snprintf(name, sizeof name, "%s", n.name); return; }
  std::snprintf(name, sizeof name, "#%06x", rgb);
}

void number_leaves(const BehaviourTree& bt, int node, int& next, std::vector<int>& numbers) {
  const BtNode& n = bt.nodes[static_cast<std::size_t>(node)];
  if (n.type == BtNodeType::Action) numbers[static_cast<std::size_t>(node)] = next++;
  for (const int child : n.children) number_leaves(bt, child, next, numbers);
}

bool reads_demiurge_floor(const ControlSoftware& software) {
  const auto demiurge = [](const ModuleInstance& m) { return m.id / 10 == 3 || m.id / 10 == 5; };
  for (const FsmState& s : software.fsm.states)
    if (demiurge(s.behaviour)) return true;
  for (const BtNode& n : software.bt.nodes)
    if (n.type == BtNodeType::Action && demiurge(n.module)) return true;
  return software.architecture == Architecture::NeuralNetwork;
}

}  // namespace

TraceWriter::TraceWriter(std::ostream& out) : out_(out) {
  out_ << "tick,robot,x,y,yaw,v_left,v_right,state,behaviour,ground,led,objective\n";
}

void TraceWriter::start(const Simulation& sim) {
  const ControlSoftware& software = sim.software();
  const auto robots = static_cast<std::size_t>(sim.swarm().size);
  leaf_number_.assign(software.bt.nodes.size(), -1);
  int next = 0;
  if (!software.bt.nodes.empty()) number_leaves(software.bt, 0, next, leaf_number_);
  previous_state_.assign(robots, 0);
  previous_left_.assign(robots, 0.0);
  previous_right_.assign(robots, 0.0);
  previous_led_.assign(robots, 0);
  demiurge_floor_ = reads_demiurge_floor(software);
}

std::pair<int, int> TraceWriter::what_ran(const Simulation& sim, int robot) const {
  const ControlSoftware& software = sim.software();
  const int current = sim.fsm_state(robot);
  switch (software.architecture) {
    case Architecture::Fsm: {
      // The behaviour of the state the robot was in before this tick's transition check.
      const int before = previous_state_[static_cast<std::size_t>(robot)];
      return {current, software.fsm.states[static_cast<std::size_t>(before)].behaviour.id % 10};
    }
    case Architecture::BehaviourTree:
      if (current < 0) return {-1, -1};
      return {leaf_number_[static_cast<std::size_t>(current)], software.bt.nodes[static_cast<std::size_t>(current)].module.id % 10};
    case Architecture::NeuralNetwork: break;
  }
  return {-1, -1};
}

void TraceWriter::on_tick(const Simulation& sim) {
  const SwarmState& s = sim.swarm();
  if (sim.tick() == 0) start(sim);
  char line[320], led[16], ran[64];
  for (int i = 0; i < s.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    ran[0] = '\0';
    if (sim.tick() > 0) {
      const auto [state, behaviour] = what_ran(sim, i);
      const ReferenceModel& rm = sim.reference_model(i);
      const double ground = demiurge_floor_ ? rm.ground_demiurge : rm.ground;
      if (behaviour < 0) std::snprintf(ran, sizeof ran, "%d,,%.9g", state, ground);
      else std::snprintf(ran, sizeof ran, "%d,%d,%.9g", state, behaviour, ground);
    } else {
      std::snprintf(ran, sizeof ran, ",,");
    }
    led_name(previous_led_[r], led);
    std::snprintf(line, sizeof line, "%d,epuck%d,%.9g,%.9g,%.9g,%.9g,%.9g,%s,%s,%.17g\n", sim.tick(), i, s.position[r].x,
                  s.position[r].y, s.yaw[r], previous_left_[r], previous_right_[r], ran, led, sim.score());
    out_ << line;
    previous_state_[r] = sim.fsm_state(i);
    previous_left_[r] = s.wheel_left[r];
    previous_right_[r] = s.wheel_right[r];
    previous_led_[r] = s.led[r];
  }
}

}  // namespace sd
