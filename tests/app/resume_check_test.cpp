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

TEST(ResumeCheck, Version3GoesOnOnlyForSwarmsItScoredRight) {
  // Version 4 changed only swarms of more than 362 robots (16-bit pair indices).
  static_assert(kResultsVersion == 4, "a new version decides anew which older runs it reproduces");
  EXPECT_EQ(results_version_refusal("the design", 3, 20), "");
  EXPECT_EQ(results_version_refusal("the design", 3, 362), "");
  const std::string refusal = results_version_refusal("the design in d", 3, 363);
  EXPECT_NE(refusal.find("the design in d was run by a swarmdesign whose simulations score differently (results version 3, this one 4)"),
            std::string::npos)
      << refusal;
}

TEST(ResumeCheck, OlderVersionsNeverGoOn) {
  EXPECT_NE(results_version_refusal("the design", 1, 20), "");
  EXPECT_NE(results_version_refusal("the design", 2, 20), "");
  EXPECT_NE(results_version_refusal("the design", 5, 20), "") << "a newer build's runs do not go on here either";
}

}  // namespace
}  // namespace sd::app
