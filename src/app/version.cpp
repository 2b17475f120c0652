#include "app/version.hpp"

#include "evaluation/results_version.hpp"

namespace sd::app {

std::string version_line() {
  return std::string("swarmdesign ") + SWARMDESIGN_VERSION + " (results version " + std::to_string(kResultsVersion) + ")";
}

}  // namespace sd::app
