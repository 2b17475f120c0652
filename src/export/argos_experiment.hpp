#pragma once
// A mission as an ARGoS3 experiment file (.argos) for ARGoS3-AutoMoDe's automode_main:
// the experiment's length at 10 ticks per second, the loop functions the mission file names
// (experiments-loop-functions: they draw the floor, place the robots and score the run), the
// automode controller with the sensors, actuators and noise of the mission's robot model,
// the walls as boxes, the lights, and the e-pucks epuck0 ... epuck<N-1>: unique ids, since
// AutoMoDe's controller takes a robot's id from the digits after "epuck" (upstream files
// name them epuck_01_30 ..., which all read as id 0, so that neighbours drop each other's
// messages as their own). Written with pugixml, so every attribute is escaped.
#include <cstdint>
#include <string>
#include <vector>

#include "missions/mission.hpp"

namespace sd::argos {

struct ExperimentOptions {
  /// Prefix of the mission's loop-function library (the experiments-loop-functions build folder).
  std::string loop_functions_dir = "experiments-loop-functions/build";
  /// The automode controller's library (ARGoS3-AutoMoDe's build).
  std::string automode_library = "ARGoS3-AutoMoDe/build/src/libautomode.so";
  /// Its XML tag: automode_controller, or automode_controller_bt for automode_main_bt's trees.
  std::string controller_tag = "automode_controller";
  /// Seeds the e-pucks' start poses written in the file (loop functions re-place them).
  std::uint64_t placement_seed = 1;
  /// The robot model of the file this one will be compared with run by run (a pseudo-reality
  /// sample's file: the design model's). Where the two make ARGoS create different random
  /// generators, the file and the notes say so and how to pair them. nullptr: no such file.
  const RobotModel* paired_with = nullptr;
  /// An FSM's configuration (as automode_main takes it) to write as the controller's default
  /// (`<params fsm-config>`), so automode_main runs it when given none; empty: none.
  std::string default_fsm_config;
};

struct Experiment {
  std::string xml;
  int boxes = 0;                    // walls written as <box>
  int walls_left_to_loop_functions = 0;
  std::vector<std::string> notes;   // what a user must know (printed on stderr)
};

Experiment argos_experiment(const Mission& mission, const ExperimentOptions& options = {});

}  // namespace sd::argos
