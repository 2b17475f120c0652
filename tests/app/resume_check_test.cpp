// Which kept runs may go on after an upgrade: those whose scores this build reproduces.
#include <gtest/gtest.h>

#include "app/resume_check.hpp"
#include "evaluation/results_version.hpp"

namespace sd::app {
namespace {

TEST(ResumeCheck, RunsOfThisVersionGoOnWhateverTheSwarm) {
  EXPECT_EQ(results_version_refusal("the design", kResultsVersion, 20), "");
  EXPECT_EQ(results_version_refusal("the design", kResultsVersion, 1000), "");
}

TEST(ResumeCheck, Versions3To5NoLongerGoOn) {
  // Version 5 changed the RAB range of the catalogue's missions and Coconut, version 6
  // TuttiFrutti's floor filter, whatever the swarm.
  static_assert(kResultsVersion == 6, "a new version decides anew which older runs it reproduces");
  for (int version : {3, 4, 5})
    for (int robots : {20, 362, 1000}) EXPECT_NE(results_version_refusal("the design", version, robots), "") << version;
  const std::string refusal = results_version_refusal("the design in d", 4, 20);
  EXPECT_NE(refusal.find("the design in d was run by a swarmdesign whose simulations score differently (results version 4, this one 6)"),
            std::string::npos)
      << refusal;
}

TEST(ResumeCheck, OlderVersionsNeverGoOn) {
  EXPECT_NE(results_version_refusal("the design", 1, 20), "");
  EXPECT_NE(results_version_refusal("the design", 2, 20), "");
  EXPECT_NE(results_version_refusal("the design", 7, 20), "") << "a newer build's runs do not go on here either";
}

}  // namespace
}  // namespace sd::app
