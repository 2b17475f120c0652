#pragma once
// Reading the mission a command was given (a catalogue name or a file): a mission that
// cannot be loaded is the user's mistake, reported as a usage error.
#include <string>

#include "missions/catalogue.hpp"

namespace sd::cli {

Mission load_mission_or_usage(const std::string& name);

}  // namespace sd::cli
