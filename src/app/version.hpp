#pragma once
// Which SwarmDesign this is, as --version prints it and as a cluster's swarmdesign must print it
// for its runs to score as ours (cluster-check compares the two).
#include <string>

namespace sd::app {

/// "swarmdesign 0.1.0 (results version N)".
std::string version_line();

}  // namespace sd::app
