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
namespace sd {

inline constexpr int kResultsVersion = 3;

}  // namespace sd
