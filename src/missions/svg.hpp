#pragma once
// Drawing of a mission's arena: walls, LED walls, floor patches clipped to the walls, the
// objective's zones and grid, lights, start region; fitted to the arena. Outside the walls the
// drawing is #eef1f5, a colour no floor has.
#include <string>

#include "missions/mission.hpp"

namespace sd {

std::string mission_svg(const Mission& mission);

}  // namespace sd
