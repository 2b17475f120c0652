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
//      pushed the wrong pairs. Up to 362 robots every score is version 3's, bit for bit, so
//      runs of version 3 on such swarms go on.
namespace sd {

inline constexpr int kResultsVersion = 4;

/// The largest swarm that version 3 scored as this build does.
inline constexpr int kVersion3ScoredRightUpToRobots = 362;

/// True if runs kept under `version` score as this build's for a swarm of `robots`.
constexpr bool scores_as_this_build(int version, int robots) {
  return version == kResultsVersion || (version == 3 && robots <= kVersion3ScoredRightUpToRobots);
}

}  // namespace sd
