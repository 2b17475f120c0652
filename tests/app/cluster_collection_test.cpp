// Reads of a cluster project's experiments are pure (issue #54): listing them, as status, the
// web pages and Python do, starts no process and no simulation; only collecting
// (collect_cluster_experiments, and the web server's ClusterCollector ticker) reaches the
// cluster. The cluster here is a host that does not resolve: reaching it at all leaves its
// one-line reason as the array's note, so an empty note proves nothing reached for it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "app/accounts.hpp"
#include "app/cluster_collector.hpp"
#include "app/cluster_experiments.hpp"
#include "app/experiment_job.hpp"
#include "app/projects.hpp"
#include "experiments/protocol.hpp"
#include "storage/cluster_jobs.hpp"
#include "storage/experiments.hpp"
#include "storage/lease.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

using namespace std::chrono_literals;

class ClusterCollection : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() / ("sd-cluster-collection-" + std::to_string(::getpid()) + "-" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    home_.emplace(root_);
    user_ = app::sign_up(*home_, "alice", "correct horse battery");
    project_ = app::create_project(*home_, user_, "c", app::ClusterRequest{"no-such-cluster.invalid", "alice", "", ""});
    app::select_project(*home_, user_, "c");
    std::filesystem::create_directories(project_.folder);

    // An experiment whose array Slurm took: what submit_cluster_experiment leaves behind.
    experiments::Protocol protocol;
    protocol.name = "tiny";
    protocol.designs = 2;
    protocol.assessment_seeds = 3;
    protocol.missions = {{write_short_mission(project_.folder, 2).string(), 1, {{"alone", "automode", {"fsm"}, {"chocolate"}}}}};
    const app::PlannedExperiment plan = app::plan_experiment(protocol);
    storage::Experiments store(home_->workspace(), project_);
    // Owned by the Slurm array (as submit_cluster_experiment records it), so it runs while Slurm says.
    const std::string owner = storage::owner_text(storage::SlurmJob{"array", "no-such-cluster.invalid"});
    experiment_ = store.start("tiny", experiments::to_json(plan.protocol).dump(), plan.designs, owner).first;
    std::vector<std::int64_t> tasks;
    for (const auto& d : store.designs(experiment_.id)) tasks.push_back(d.id);
    storage::ClusterJobs(home_->workspace(), project_).array_submitted(experiment_.id, "4242", "/nowhere", "{}", tasks);
  }
  void TearDown() override {
    home_.reset();
    std::filesystem::remove_all(root_);
  }

  storage::ClusterArrayJob array() { return *storage::ClusterJobs(home_->workspace(), project_).find_array(experiment_.id); }

  std::filesystem::path root_;
  std::optional<app::Home> home_;
  storage::User user_;
  storage::Project project_;
  storage::Experiment experiment_;
};

TEST_F(ClusterCollection, ListingAClusterProjectsExperimentsReachesNothingAndCollectingDoes) {
  for (int poll = 0; poll < 3; ++poll) {
    const auto progress = app::experiments_progress(*home_, user_, "c");
    ASSERT_EQ(progress.size(), 1u);
    EXPECT_EQ(progress[0].experiment.state, storage::DesignState::running);
    EXPECT_EQ(progress[0].designs_done, 0);
  }
  EXPECT_EQ(array().note, "") << "a read reached for the cluster";
  EXPECT_EQ(array().slurm_state, "PENDING");  // as submitted: never observed

  const app::ClusterCollection collected = app::collect_cluster_experiments(*home_, user_, "c");
  EXPECT_EQ(collected.experiments, 1);
  EXPECT_EQ(collected.designs_home, 0);
  EXPECT_EQ(collected.still_running, 1);  // unreachable is not ended: it is asked again next time
  EXPECT_NE(array().note.find("no-such-cluster.invalid"), std::string::npos) << array().note;
}

TEST_F(ClusterCollection, TheServersTickerCollectsTheProjectsItFollowsAndNothingElse) {
  app::ClusterCollector ticker(root_, 50ms);
  std::this_thread::sleep_for(300ms);  // several ticks with nothing followed
  EXPECT_EQ(array().note, "");
  ticker.follow(user_, "c");
  for (const auto end = std::chrono::steady_clock::now() + 30s; array().note.empty() && std::chrono::steady_clock::now() < end;)
    std::this_thread::sleep_for(20ms);
  EXPECT_NE(array().note.find("no-such-cluster.invalid"), std::string::npos) << array().note;
  EXPECT_EQ(ticker.followed(), 1u);  // still running there: still followed

  // Once nothing runs in it, the project is forgotten.
  storage::Experiments(home_->workspace(), project_).finish(experiment_.id);
  ticker.tick();
  EXPECT_EQ(ticker.followed(), 0u);
}

}  // namespace
}  // namespace sd::test
