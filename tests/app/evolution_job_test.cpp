// EvoStick as a job honours the cancel token as a design does: it stops after the generation it
// is in, once that generation's state is in the file, and resuming the file ends exactly as the
// uninterrupted evolution.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/evolution_job.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

class EvolutionJob : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("sd-evo-" + std::to_string(::getpid()) + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  app::EvolutionRequest request(const std::string& state) const {
    app::EvolutionRequest r;
    r.mission = write_short_mission(folder_).string();
    r.settings.population = 6;
    r.settings.evaluations = 2;
    r.settings.elites = 2;
    r.settings.generations = 4;
    r.settings.seed = 3;
    r.state = (folder_ / state).string();
    return r;
  }
  std::filesystem::path folder_;
};

TEST_F(EvolutionJob, CancelledAfterAGenerationItStopsWithItsStateSavedAndResumesToTheUninterruptedResult) {
  const app::EvolutionOutcome whole = app::start_evolution(request("whole.json"), {});
  ASSERT_FALSE(whole.cancelled);

  app::CancelToken token;
  app::EvolutionRun run;
  run.threads = 1;
  run.cancel = &token;
  int generations_run = 0;
  run.progress = [&](const evostick::GenerationRecord&, int) {
    if (++generations_run == 2) token.cancel();
  };
  const app::EvolutionOutcome stopped = app::start_evolution(request("cancelled.json"), run);
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_TRUE(stopped.control_software.empty());
  EXPECT_EQ(generations_run, 2);

  int resumed_generations = 0;
  app::EvolutionRun rest;
  rest.progress = [&](const evostick::GenerationRecord&, int) { ++resumed_generations; };
  const app::EvolutionOutcome resumed = app::resume_evolution((folder_ / "cancelled.json").string(), rest);
  EXPECT_FALSE(resumed.cancelled);
  EXPECT_EQ(resumed_generations, 2) << "only the generations left run";
  EXPECT_EQ(resumed.control_software, whole.control_software);
  EXPECT_EQ(resumed.result.best_mean, whole.result.best_mean);
  EXPECT_EQ(resumed.result.history, whole.result.history);
}

}  // namespace
}  // namespace sd::test
