// Leases under contention, as a server lives them: job threads renew their designs' heartbeats
// (LeaseKeeper's beat, each on its own connection) while request threads sweep the same
// projects for dead owners. A live owner is never swept, no heartbeat is lost to a busy
// database, and a dead owner's row is swept to interrupted and taken over once. Under TSan
// (scripts/sanitizers.sh) this is also the race detector's view of leases.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <thread>
#include <vector>

#include "app/accounts.hpp"
#include "app/home.hpp"
#include "app/projects.hpp"
#include "storage/designs.hpp"
#include "storage/errors.hpp"
#include "storage/lease.hpp"
#include "storage/projects.hpp"

namespace sd::test {
namespace {

constexpr int kProjects = 3;
constexpr int kBeats = 40;   // per renewing job
constexpr int kSweeps = 40;  // per sweeping request thread

class LeaseRace : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() / (std::string("sd-lease-race-") + std::to_string(::getpid()));
    std::filesystem::remove_all(root_);
    app::Home home(root_);
    user_ = app::sign_up(home, "alice", "correct horse battery");
    for (int p = 0; p < kProjects; ++p) {
      app::create_project(home, user_, name(p), std::nullopt);
      app::select_project(home, user_, name(p));
      app::set_mission(home, user_, "aac");
      app::set_budget(home, user_, "1000");
    }
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  static std::string name(int p) { return std::string("p").append(std::to_string(p)); }
  storage::Project project(app::Home& home, int p) const { return storage::Projects(home.workspace(), user_).get(name(p)); }

  std::filesystem::path root_;
  storage::User user_;
};

// Owners on another machine live by their heartbeat alone, so a sweep that read a torn or lost
// heartbeat would interrupt them; each project's job renews while two request threads sweep.
TEST_F(LeaseRace, HeartbeatsRacingSweepsKeepEveryLiveLeaseAndSweepTheDeadOne) {
  std::vector<std::int64_t> ids;
  std::vector<std::string> owners;
  {
    app::Home home(root_);
    for (int p = 0; p < kProjects; ++p) {
      owners.push_back(storage::owner_text(storage::ServerThread{{"another-boot", "1", 4000 + p}, std::string("web-") + std::to_string(p)}));
      ids.push_back(storage::Designs(home.workspace(), project(home, p)).start({"fsm", "chocolate", 1, owners.back()}).id);
    }
  }
  // A fourth project's design belongs to a process of this machine that is gone.
  const std::string dead_owner = storage::owner_text(storage::ServerThread{{"", "", 0x7ffffff0}, "web-dead"});
  std::int64_t dead_id = 0;
  {
    app::Home home(root_);
    app::create_project(home, user_, "dead", std::nullopt);
    app::select_project(home, user_, "dead");
    app::set_mission(home, user_, "aac");
    app::set_budget(home, user_, "1000");
    const auto dead = storage::Projects(home.workspace(), user_).get("dead");
    storage::Designs designs(home.workspace(), dead);
    dead_id = designs.start({"fsm", "chocolate", 1, dead_owner}).id;
  }

  std::atomic<int> lost_beats{0}, swept_live{0}, errors{0}, takeovers{0};
  std::vector<std::thread> threads;
  for (int p = 0; p < kProjects; ++p)
    threads.emplace_back([&, p] {
      app::Home home(root_);  // a job's own connection, as LeaseKeeper opens one
      const storage::Project pr = project(home, p);
      for (int b = 0; b < kBeats; ++b) try {
          if (!storage::Designs(home.workspace(), pr).heartbeat(ids[p], owners[p])) ++lost_beats;
        } catch (const std::exception&) {
          ++errors;
        }
    });
  for (int s = 0; s < 2; ++s)
    threads.emplace_back([&] {
      app::Home home(root_);  // a request's connection
      const storage::Project dead = storage::Projects(home.workspace(), user_).get("dead");
      for (int i = 0; i < kSweeps; ++i) try {
          for (int p = 0; p < kProjects; ++p)
            if (storage::Designs(home.workspace(), project(home, p)).latest()->state != storage::DesignState::running)
              ++swept_live;
          storage::Designs designs(home.workspace(), dead);
          if (designs.latest()->state == storage::DesignState::interrupted) {
            designs.resume(dead_id, storage::owner_text(storage::server_thread("web-new")));
            ++takeovers;
          }
        } catch (const storage::Conflict&) {
          // The other request thread took the dead design over first: one takeover only.
        } catch (const std::exception&) {
          ++errors;
        }
    });
  for (auto& t : threads) t.join();

  EXPECT_EQ(errors.load(), 0) << "a busy database waits, it does not fail";
  EXPECT_EQ(lost_beats.load(), 0);
  EXPECT_EQ(swept_live.load(), 0) << "a fresh heartbeat is never swept";
  EXPECT_EQ(takeovers.load(), 1);
  app::Home home(root_);
  for (int p = 0; p < kProjects; ++p) {
    const auto d = storage::Designs(home.workspace(), project(home, p)).latest();
    EXPECT_EQ(d->state, storage::DesignState::running);
    EXPECT_EQ(d->owner, owners[p]);
  }
  const auto taken = storage::Designs(home.workspace(), storage::Projects(home.workspace(), user_).get("dead")).latest();
  EXPECT_EQ(taken->id, dead_id);
  EXPECT_EQ(taken->state, storage::DesignState::running);
}

}  // namespace
}  // namespace sd::test
