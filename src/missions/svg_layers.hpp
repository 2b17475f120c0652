#pragma once
// Parts of a mission's drawing (svg.cpp) that follow its geometry: the arena's outline (the
// convex hull of its walls, which clips the floor) and the objective's zones and grid.
#include <string>
#include <vector>

#include "missions/mission.hpp"

namespace sd {

/// The convex hull of every wall's corners, counter-clockwise; empty without walls (an
/// unbounded workspace).
std::vector<Vec2> arena_outline(const Mission& mission);

/// SVG elements in world metres (inside the y-up group): the objective's zones as dashed
/// outlines and a grid objective's cells; `lo`/`hi` bound half-planes and rings.
std::string objective_layer(const Mission& mission, Vec2 lo, Vec2 hi);

}  // namespace sd
