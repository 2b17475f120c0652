// A cluster project reads its design's progress from the document `design-status --json` prints
// on the cluster: what it writes comes back unchanged, and a damaged document (a number no
// count can hold) is refused in one line instead of converted with undefined behaviour.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "app/documents/design.hpp"
#include "refusal.hpp"

namespace sd::app {
namespace {

storage::DesignProgress progress() {
  storage::DesignProgress p;
  p.started = true;
  p.phase = "racing";
  p.iteration = 3;
  p.nb_iterations = 7;
  p.budget = 20000;
  p.experiments_used = 8123;
  p.race_budget = 2400;
  p.race_configurations = 18;
  p.configurations_sampled = 51;
  p.best = storage::ConfigurationScore{42, "--fsm-config --nstates 1 --s0 4 --att0 3", 1234.5, 17};
  return p;
}

TEST(ClusterStatusDocument, WhatTheClusterPrintsComesBackUnchanged) {
  const storage::DesignProgress p = progress();
  const storage::DesignProgress back = stored_progress_from_document(stored_progress_document(p));
  EXPECT_EQ(back.phase, p.phase);
  EXPECT_EQ(back.iteration, p.iteration);
  EXPECT_EQ(back.nb_iterations, p.nb_iterations);
  EXPECT_EQ(back.budget, p.budget);
  EXPECT_EQ(back.experiments_used, p.experiments_used);
  EXPECT_EQ(back.race_budget, p.race_budget);
  EXPECT_EQ(back.race_configurations, p.race_configurations);
  EXPECT_EQ(back.configurations_sampled, p.configurations_sampled);
  ASSERT_TRUE(back.best.has_value());
  EXPECT_EQ(back.best->id, 42);
  EXPECT_EQ(back.best->runs, 17);
}

TEST(ClusterStatusDocument, ADamagedDocumentIsRefusedNamingTheField) {
  const nlohmann::json good = stored_progress_document(progress());
  const auto refusal = [](const nlohmann::json& document) {
    return test::refusal_of<std::runtime_error>([&] { return stored_progress_from_document(document); });
  };
  nlohmann::json huge = good;
  huge["iteration"] = 1e300;
  EXPECT_EQ(refusal(huge), "the cluster's status document: iteration is not an integer in range");
  nlohmann::json wraps = good;
  wraps["race_configurations"] = std::int64_t{1} << 40;
  EXPECT_EQ(refusal(wraps), "the cluster's status document: race_configurations is not an integer in range");
  nlohmann::json fraction = good;
  fraction["best"]["runs"] = 2.5;
  EXPECT_EQ(refusal(fraction), "the cluster's status document: runs is not an integer in range");
}

}  // namespace
}  // namespace sd::app
