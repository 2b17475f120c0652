#pragma once
// Drawing of a mission's arena: walls, LED walls, floor patches, lights, start region.
#include <string>

#include "missions/mission.hpp"

namespace sd {

std::string mission_svg(const Mission& mission);

}  // namespace sd
