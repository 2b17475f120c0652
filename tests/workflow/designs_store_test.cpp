// The designs table as run-design and status will use it (through storage, not the binary:
// those commands are wired when the optimiser and evaluator are merged).
#include <gtest/gtest.h>
#include <unistd.h>

#include "storage/accounts.hpp"
#include "storage/designs.hpp"
#include "storage/errors.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

constexpr int kDeadPid = 0x7ffffff0;  // above any pid_max: no such process

class workflow_designs : public WorkflowTest {
 protected:
  storage::Project project(const std::string& name, bool configured = true) {
    storage::Projects projects(workspace(), owner());
    if (projects.list().empty() || !has(projects, name)) projects.create(name, std::nullopt);
    projects.select(name);
    if (configured) {
      projects.set_mission("aac");
      projects.set_budget(1000);
    }
    return projects.get(name);
  }
  storage::Workspace& workspace() {
    if (!workspace_) workspace_ = std::make_unique<storage::Workspace>(home());
    return *workspace_;
  }
  const storage::User& owner() {
    if (!owner_) owner_ = storage::create_user(workspace().database(), "alice", "correct horse battery");
    return *owner_;
  }
  static storage::DesignRequest request(int pid) { return {"fsm,bt", "chocolate", 42, pid}; }

 private:
  static bool has(storage::Projects& projects, const std::string& name) {
    for (const auto& p : projects.list())
      if (p.name == name) return true;
    return false;
  }
  std::unique_ptr<storage::Workspace> workspace_;
  std::optional<storage::User> owner_;
};

TEST_F(workflow_designs, StartCopiesTheProjectSettingsAndGivesTheDesignItsOwnFolder) {
  storage::Designs designs(workspace(), project("p"));
  const auto design = designs.start(request(::getpid()));
  EXPECT_EQ(design.state, storage::DesignState::running);
  EXPECT_EQ(design.mission, "aac");
  EXPECT_EQ(design.budget, 1000);
  EXPECT_EQ(design.architectures, "fsm,bt");
  EXPECT_EQ(design.folder, home() / "users" / "alice" / "projects" / "p" / "designs" / std::to_string(design.id));
  EXPECT_TRUE(std::filesystem::is_directory(design.folder));

  // Changing the project later does not rewrite the design's history.
  storage::Projects(workspace(), owner()).set_budget(5);
  EXPECT_EQ(storage::Designs(workspace(), project("p", false)).latest()->budget, 1000);
}

TEST_F(workflow_designs, ASecondRunningDesignInTheSameProjectIsRefused) {
  storage::Designs designs(workspace(), project("p"));
  designs.start(request(::getpid()));
  EXPECT_THROW(designs.start(request(::getpid())), storage::Conflict);
  EXPECT_EQ(designs.list().size(), 1u);
  // Even a direct insert cannot make two running designs: the schema forbids it.
  EXPECT_THROW(workspace().database().execute(
                   "INSERT INTO designs (project_id, architectures, flavours, mission, budget, seed, path, created_at, "
                   "updated_at) SELECT project_id, architectures, flavours, mission, budget, seed, path, 0, 0 FROM designs"),
               storage::DatabaseError);
  // Another project may run at the same time.
  storage::Designs other(workspace(), project("q"));
  EXPECT_NO_THROW(other.start(request(::getpid())));
}

TEST_F(workflow_designs, AKilledDesignShowsAsInterruptedAndCanBeResumed) {
  storage::Designs designs(workspace(), project("p"));
  const auto killed = designs.start(request(kDeadPid));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);

  const auto resumed = designs.resume(killed.id, ::getpid());
  EXPECT_EQ(resumed.state, storage::DesignState::running);
  EXPECT_EQ(resumed.pid, ::getpid());
  EXPECT_EQ(resumed.folder, killed.folder);
  EXPECT_THROW(designs.resume(killed.id, ::getpid()), storage::Conflict);  // it runs again

  designs.finish(killed.id, "--fsm-config --nstates 1 --s0 0", 12.5);
  const auto done = designs.latest();
  EXPECT_EQ(done->state, storage::DesignState::finished);
  EXPECT_EQ(done->best_config, "--fsm-config --nstates 1 --s0 0");
  EXPECT_EQ(done->best_score, 12.5);
  EXPECT_TRUE(done->finished_at.has_value());
  EXPECT_THROW(designs.finish(killed.id, "x", 1.0), storage::Conflict);
}

TEST_F(workflow_designs, ADeadRunningDesignDoesNotBlockANewOne) {
  storage::Designs designs(workspace(), project("p"));
  const auto killed = designs.start(request(kDeadPid));
  const auto fresh = designs.start(request(::getpid()));
  EXPECT_NE(fresh.id, killed.id);
  EXPECT_EQ(designs.list().front().state, storage::DesignState::interrupted);
}

TEST_F(workflow_designs, APidNowHeldByAnotherProcessDoesNotKeepADesignRunning) {
  storage::Designs designs(workspace(), project("p"));
  const auto design = designs.start(request(::getpid()));
  EXPECT_EQ(design.process, storage::process_identity(::getpid()));
  EXPECT_FALSE(design.process.empty());
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);
  // As after a reboot: the same pid, alive, but another process (another boot, another start).
  workspace().database().execute("UPDATE designs SET process = 'another-boot/12345' WHERE id = " + std::to_string(design.id));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);
  const auto fresh = designs.start(request(::getpid()));
  EXPECT_NE(fresh.id, design.id);
  EXPECT_EQ(designs.list().front().state, storage::DesignState::interrupted);
  // Rows written before the identity was kept are judged by their pid alone, as before.
  workspace().database().execute("UPDATE designs SET process = NULL WHERE id = " + std::to_string(fresh.id));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);
}

TEST(ProcessIdentity, NamesThisBootAndTheProcessStart) {
  const std::string mine = storage::process_identity(::getpid());
  EXPECT_EQ(mine, storage::process_identity(::getpid()));  // stable
  EXPECT_NE(mine.find('/'), std::string::npos);
  EXPECT_NE(mine, storage::process_identity(1));             // init started before us
  EXPECT_EQ(storage::process_identity(kDeadPid), "");
}

TEST_F(workflow_designs, ClusterProjectsAndUnconfiguredProjectsCannotStartADesign) {
  storage::Projects projects(workspace(), owner());
  projects.create("remote", storage::ClusterConnection{"hpc.example.org", "al"});
  projects.select("remote");
  projects.set_mission("aac");
  projects.set_budget(10);
  try {
    storage::Designs(workspace(), projects.get("remote")).start(request(::getpid()));
    FAIL() << "a cluster project started a design";
  } catch (const storage::Conflict& e) {
    EXPECT_NE(std::string(e.what()).find("not available yet"), std::string::npos);
  }
  EXPECT_THROW(storage::Designs(workspace(), project("bare", false)).start(request(::getpid())), storage::NotFound);
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
}

TEST_F(workflow_designs, SeedsKeepAll64Bits) {
  storage::Designs designs(workspace(), project("p"));
  auto wide = request(::getpid());
  wide.seed = 0xFEDCBA9876543210ULL;
  EXPECT_EQ(designs.start(wide).seed, 0xFEDCBA9876543210ULL);
}

}  // namespace
}  // namespace sd::test
