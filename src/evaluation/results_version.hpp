#pragma once
// Which simulator produced a score. Bump kResultsVersion with every change that gives any
// (mission, control software, seed) another score: the physics, a sensor, a module, the
// order or kind of random draws, an objective. A design records the version it started
// with and refuses to resume under another, because one race would otherwise compare runs of
// two simulators.
//   1: up to November 2026 (glibc's sin, cos, exp and log; polar-method normals)
//   2: core/math.hpp's elementary functions and ziggurat normals, the same on every CPU
//   3: calibrated on SCA, Maple trees and TuttiFrutti (December 2026): walls a loop function
//      adds after placement, Maple's own module laws, the TuttiFrutti scenarios' RAB range,
//      the camera's square field and RM3.0's ground filter
//   4: pair indices of 32 bits (December 2026): with more than 362 robots, version 3 sensed and
//      pushed the wrong pairs. Up to 362 robots every score was version 3's, bit for bit.
//   5: the catalogue's missions hear neighbours within their scenario files' RAB range, 0.7 m
//      (argos3-epuck reads the actuator's `range`), and Coconut as Demiurge runs it: its RM3.0
//      floor filter (10 steps; Arlequin's floor conditions too), behaviours 32-35 keeping their
//      counters across states, grid exploration scored / 1000 (December 2026).
//      Versions 3 and 4 score the catalogue's missions differently, so none of their runs go on.
//   6: TuttiFrutti's floor conditions read RM1.2's filter (< 0.03 / > 0.85), as the RM3.0 of
//      its code base (demiurge-epuck-dao branch tuttifrutti) does, not 0.1 / 0.8 (December 2026).
namespace sd {

inline constexpr int kResultsVersion = 6;

/// True if runs kept under `version` score as this build's for a swarm of `robots` (a new
/// version may keep older runs that it scores alike; version 6 keeps none).
constexpr bool scores_as_this_build(int version, [[maybe_unused]] int robots) { return version == kResultsVersion; }

}  // namespace sd
