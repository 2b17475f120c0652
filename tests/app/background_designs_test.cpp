// A server's background designs (app/background_designs.hpp) stopped and resumed as fast as a
// page can: the row reads "interrupted" as soon as the stopped job has released it, while its
// thread may still be winding down; a resume at that moment must get a thread of its own
// without disturbing the old one (it once destroyed the new thread unjoined: std::terminate).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "app/accounts.hpp"
#include "app/background_designs.hpp"
#include "app/background_experiments.hpp"
#include "app/errors.hpp"
#include "app/experiment_backends.hpp"
#include "storage/experiments.hpp"
#include "app/projects.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

TEST(BackgroundDesigns, ADesignResumedTheMomentItReadsInterruptedRunsAgain) {
  const auto root = std::filesystem::temp_directory_path() / (std::string("sd-background-") + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  app::Home home(root);
  const storage::User user = app::sign_up(home, "alice", "correct horse battery");
  const auto folder = root / "users" / "alice" / "projects" / "p";
  std::filesystem::create_directories(folder);
  app::create_project(home, user, "p", std::nullopt);
  app::select_project(home, user, "p");
  app::set_mission(home, user, write_short_mission(folder, 2).string());
  app::set_budget(home, user, "50000");

  app::DesignLaunch launch;
  launch.design.space.fsm = true;
  launch.design.space.flavours = {Flavour::Chocolate};
  launch.design.seed = 5;
  launch.design.project = "p";
  std::int64_t id = 0;
  {
    app::BackgroundDesigns designs("test");
    for (int round = 0; round < 3; ++round) {
      const app::StartedDesign started = designs.start(home, user, launch);
      EXPECT_EQ(started.resumed, round > 0);
      if (round == 0) id = started.design.id;
      EXPECT_EQ(started.design.id, id);
      designs.stop(home, started.project, started.design);
      // No pause: the next start comes the moment the row says the job let it go.
      storage::Designs rows(home.workspace(), started.project);
      while (rows.latest()->state == storage::DesignState::running) {
      }
      ASSERT_EQ(rows.latest()->state, storage::DesignState::interrupted);
    }
  }
  const auto last = storage::Designs(home.workspace(), storage::Projects(home.workspace(), user).get("p")).latest();
  EXPECT_EQ(last->id, id);
  EXPECT_EQ(last->state, storage::DesignState::interrupted);
  std::filesystem::remove_all(root);
}

// The same request answers alike in the CLI and in a server: sbatch settings for a project
// that runs on this machine are refused by both backends, before anything is recorded.
TEST(BackgroundExperiments, SbatchSettingsForALocalProjectAreRefusedAsTheCliRefusesThem) {
  const auto root = std::filesystem::temp_directory_path() / (std::string("sd-background-exp-") + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  app::Home home(root);
  const storage::User user = app::sign_up(home, "alice", "correct horse battery");
  app::create_project(home, user, "p", std::nullopt);
  app::select_project(home, user, "p");
  app::ExperimentLaunch launch;
  launch.protocol.builtin = "validation";
  launch.protocol.overrides.missions = std::vector<std::string>{"aac"};
  launch.job.partition = "long";
  app::BackgroundExperiments server("test");
  std::string said_by_server, said_by_cli;
  try {
    app::launch_experiment(home, user, launch, &server);
  } catch (const app::InvalidRequest& e) {
    said_by_server = e.what();
  }
  try {
    app::launch_experiment(home, user, launch, nullptr);
  } catch (const app::InvalidRequest& e) {
    said_by_cli = e.what();
  }
  EXPECT_NE(said_by_server.find("are for a cluster project"), std::string::npos) << said_by_server;
  EXPECT_EQ(said_by_server, said_by_cli);
  EXPECT_TRUE(storage::Experiments(home.workspace(), storage::Projects(home.workspace(), user).get("p")).list().empty());
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace sd::test
