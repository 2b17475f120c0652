// The designs table as the application's design jobs use it (through storage, not the binary):
// starting, resuming, the lease of the job that runs a design, and how a dead owner is found.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <variant>

#include "storage/accounts.hpp"
#include "storage/cluster_jobs.hpp"
#include "storage/designs.hpp"
#include "storage/experiments.hpp"
#include "storage/errors.hpp"
#include "storage/clock.hpp"
#include "storage/lease.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

constexpr int kDeadPid = 0x7ffffff0;  // above any pid_max: no such process

std::string owner_of(std::int64_t pid) { return storage::owner_text(storage::server_thread("test", pid)); }
std::string me() { return owner_of(::getpid()); }

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
  static storage::DesignRequest request(const std::string& owner) { return {"fsm,bt", "chocolate", 42, owner}; }

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
  const auto design = designs.start(request(me()));
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
  designs.start(request(me()));
  EXPECT_THROW(designs.start(request(me())), storage::Conflict);
  EXPECT_EQ(designs.list().size(), 1u);
  // Even a direct insert cannot make two running designs: the schema forbids it.
  EXPECT_THROW(workspace().database().execute(
                   "INSERT INTO designs (project_id, architectures, flavours, mission, budget, seed, path, created_at, "
                   "updated_at) SELECT project_id, architectures, flavours, mission, budget, seed, path, 0, 0 FROM designs"),
               storage::DatabaseError);
  // Another project may run at the same time.
  storage::Designs other(workspace(), project("q"));
  EXPECT_NO_THROW(other.start(request(me())));
}

TEST_F(workflow_designs, AKilledDesignShowsAsInterruptedAndCanBeResumed) {
  storage::Designs designs(workspace(), project("p"));
  const auto killed = designs.start(request(owner_of(kDeadPid)));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);

  const auto resumed = designs.resume(killed.id, me());
  EXPECT_EQ(resumed.state, storage::DesignState::running);
  EXPECT_EQ(resumed.pid, ::getpid());
  EXPECT_EQ(resumed.owner, me());
  EXPECT_EQ(resumed.folder, killed.folder);
  EXPECT_THROW(designs.resume(killed.id, me()), storage::Conflict);  // it runs again

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
  const auto killed = designs.start(request(owner_of(kDeadPid)));
  const auto fresh = designs.start(request(me()));
  EXPECT_NE(fresh.id, killed.id);
  EXPECT_EQ(designs.list().front().state, storage::DesignState::interrupted);
}

TEST_F(workflow_designs, TheListAndTheLatestDesignReportADeadDesignTheSameWay) {
  // A server killed with a design running: its row still says "running" until something
  // writes; reading it, the list and the latest design both say interrupted (the web page shows
  // both side by side).
  storage::Designs designs(workspace(), project("p"));
  const auto killed = designs.start(request(owner_of(kDeadPid)));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);
  ASSERT_EQ(designs.list().size(), 1u);
  EXPECT_EQ(designs.list().front().id, killed.id);
  EXPECT_EQ(designs.list().front().state, storage::DesignState::interrupted);
}

TEST_F(workflow_designs, ADesignIsDeletedWithItsFolderOnlyOnceItNoLongerRuns) {
  storage::Designs designs(workspace(), project("p"));
  const auto running = designs.start(request(me()));
  std::ofstream(running.folder / "design.db") << "race data";
  EXPECT_THROW(designs.remove(running.id), storage::Conflict);
  EXPECT_TRUE(std::filesystem::exists(running.folder / "design.db"));

  designs.finish(running.id, "--fsm-config --nstates 1 --s0 0", 1.0);
  const auto killed = designs.start(request(owner_of(kDeadPid)));  // reads interrupted: deletable
  designs.remove(running.id);
  EXPECT_FALSE(std::filesystem::exists(running.folder));
  ASSERT_EQ(designs.list().size(), 1u);
  EXPECT_EQ(designs.list().front().id, killed.id);
  EXPECT_TRUE(std::filesystem::is_directory(killed.folder));
  designs.remove(killed.id);
  EXPECT_TRUE(designs.list().empty());
  // Nothing hidden is left behind either.
  EXPECT_TRUE(std::filesystem::is_empty(running.folder.parent_path()));
  EXPECT_THROW(designs.remove(killed.id), storage::NotFound);

  // Another project's design is not found through this project, and stays.
  storage::Designs other(workspace(), project("q"));
  const auto theirs = other.start(request(owner_of(kDeadPid)));
  EXPECT_THROW(designs.remove(theirs.id), storage::NotFound);
  EXPECT_TRUE(std::filesystem::is_directory(theirs.folder));
}

TEST_F(workflow_designs, AProjectIsDeletedWholeButNotWhileSomethingOfItRuns) {
  storage::Projects projects(workspace(), owner());
  const storage::Project p = project("p");
  storage::Designs designs(workspace(), p);
  const auto design = designs.start(request(me()));
  std::ofstream(p.folder / "notes.txt") << "mine";
  EXPECT_THROW(projects.remove("p"), storage::Conflict);
  EXPECT_TRUE(std::filesystem::exists(p.folder / "notes.txt"));
  designs.release(design.id, me());

  const storage::Project q = project("q");  // the active one now
  std::ofstream(q.folder / "kept.txt") << "other project";
  projects.select("p");
  projects.remove("P");  // names are case-insensitive
  EXPECT_FALSE(std::filesystem::exists(p.folder));
  EXPECT_THROW(projects.get("p"), storage::NotFound);
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
  EXPECT_FALSE(projects.active().has_value());  // it was the active one
  EXPECT_TRUE(std::filesystem::exists(q.folder / "kept.txt"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(q.folder.parent_path()), {}), 1);

  // The same name makes a new, empty project.
  EXPECT_TRUE(std::filesystem::is_empty(projects.create("p", std::nullopt).folder));

  // Another user cannot delete it: for them it does not exist.
  const storage::User bob = storage::create_user(workspace().database(), "bob", "another good password");
  EXPECT_THROW(storage::Projects(workspace(), bob).remove("q"), storage::NotFound);
  EXPECT_TRUE(std::filesystem::exists(q.folder / "kept.txt"));
}

TEST_F(workflow_designs, AnOwnerOnThisMachineLivesAsLongAsItsProcess) {
  storage::Designs designs(workspace(), project("p"));
  const auto design = designs.start(request(me()));
  EXPECT_EQ(design.owner, me());
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);
  // The same pid, alive, but a process that started at another time: the pid was reused.
  const auto mine = std::get<storage::ServerThread>(*storage::parse_owner(me()));
  storage::ServerThread reused = mine;
  reused.start_time = "1";
  workspace().database().execute("UPDATE designs SET owner = '" + storage::owner_text(reused) + "' WHERE id = " + std::to_string(design.id));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);
  const auto fresh = designs.start(request(me()));
  EXPECT_NE(fresh.id, design.id);
  EXPECT_EQ(designs.list().front().state, storage::DesignState::interrupted);
  // Rows written before leases were kept are judged by their pid alone, as before.
  workspace().database().execute("UPDATE designs SET owner = NULL WHERE id = " + std::to_string(fresh.id));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);
}

TEST_F(workflow_designs, AnOwnerOnAnotherMachineLivesWhileItsHeartbeatIsFresh) {
  storage::Designs designs(workspace(), project("p"));
  const std::string remote = storage::owner_text(storage::ServerThread{{"another-boot", "777", 4242}, "rank-0"});
  const auto design = designs.start(request(remote));
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);  // just started: fresh heartbeat
  EXPECT_TRUE(designs.heartbeat(design.id, remote));
  EXPECT_FALSE(designs.heartbeat(design.id, me()));  // not my design to renew

  const auto stale = std::to_string(storage::unix_now() - storage::kLeaseSeconds - 1);
  workspace().database().execute("UPDATE designs SET heartbeat_at = " + stale);
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);
  EXPECT_NO_THROW(designs.resume(design.id, me()));  // and another job may take it over
  EXPECT_EQ(designs.latest()->owner, me());
}

TEST_F(workflow_designs, AnOwnerReleasesADesignItStopsAndHandsOneOver) {
  storage::Designs designs(workspace(), project("p"));
  const auto design = designs.start(request(me()));
  const std::string child = storage::owner_text(storage::LocalProcess{{"", "", 1}});
  EXPECT_THROW(designs.release(design.id, child), storage::Conflict);  // not its owner
  designs.set_owner(design.id, child);
  EXPECT_EQ(designs.latest()->owner, child);
  EXPECT_EQ(designs.latest()->pid, 1);
  designs.release(design.id, child);
  EXPECT_EQ(designs.latest()->state, storage::DesignState::interrupted);
}

// One Lease (storage/lease.hpp) for every leased table: the same renewal, the same refusal to
// release a lease the caller does not hold (Conflict, the row untouched), the same release, and
// the same sweep of a dead owner, for designs and for experiments.
TEST_F(workflow_designs, EveryLeasedTableKeepsTheSameLease) {
  const storage::Project p = project("p");
  storage::Designs designs(workspace(), p);
  storage::Experiments experiments(workspace(), p);
  const std::string stranger = storage::owner_text(storage::ServerThread{{"another-boot", "1", 7}, "web-1"});
  struct Table {
    std::function<std::int64_t(const std::string&)> start;
    std::function<bool(std::int64_t, const std::string&)> renew;
    std::function<void(std::int64_t, const std::string&)> release;
    std::function<storage::DesignState(std::int64_t)> state;
  };
  int n = 0;
  const std::vector<std::pair<std::string, Table>> tables = {
      {"designs",
       {[&](const std::string& o) { return designs.start(request(o)).id; },
        [&](std::int64_t id, const std::string& o) { return designs.heartbeat(id, o); },
        [&](std::int64_t id, const std::string& o) { designs.release(id, o); },
        [&](std::int64_t id) {
          for (const auto& d : designs.list())
            if (d.id == id) return d.state;
          return storage::DesignState::failed;
        }}},
      {"experiments",
       {[&](const std::string& o) { return experiments.start("e" + std::to_string(++n), "{}", {}, o).first.id; },
        [&](std::int64_t id, const std::string& o) { return experiments.heartbeat(id, o); },
        [&](std::int64_t id, const std::string& o) { experiments.release(id, o); },
        [&](std::int64_t id) {
          for (const auto& e : experiments.list())
            if (e.id == id) return e.state;
          return storage::DesignState::failed;
        }}}};
  for (const auto& [name, t] : tables) {
    const std::int64_t id = t.start(me());
    EXPECT_TRUE(t.renew(id, me())) << name;
    EXPECT_FALSE(t.renew(id, stranger)) << name;
    EXPECT_THROW(t.release(id, stranger), storage::Conflict) << name;
    EXPECT_EQ(t.state(id), storage::DesignState::running) << name << ": a refused release leaves the row as it was";
    t.release(id, me());
    EXPECT_EQ(t.state(id), storage::DesignState::interrupted) << name;
    EXPECT_THROW(t.release(id, me()), storage::Conflict) << name << ": released twice";
    const std::int64_t dead = t.start(owner_of(kDeadPid));
    EXPECT_EQ(t.state(dead), storage::DesignState::interrupted) << name << ": a dead owner's row reads interrupted";
  }
  // Each table's next start sweeps: the dead rows become interrupted in the table itself.
  EXPECT_EQ(query("SELECT count(*) FROM designs WHERE state = 'running'"), "1");
  EXPECT_EQ(query("SELECT count(*) FROM experiments WHERE state = 'running'"), "1");
  designs.start(request(me()));
  experiments.start("e9", "{}", {}, me());
  for (const std::string table : {"designs", "experiments"}) {
    EXPECT_EQ(query("SELECT count(*) FROM " + table + " WHERE state = 'running'"), "1") << table;
    EXPECT_EQ(query("SELECT count(*) FROM " + table + " WHERE state = 'interrupted'"), "2") << table;
  }
}

TEST(DesignLease, EveryOwnerKindReadsBackFromItsStoredText) {
  // The texts existing databases hold (schema.cpp's migration 3 wrote "<process>/<pid>/cli").
  const auto cli = storage::parse_owner("boot/123/42/cli");
  ASSERT_TRUE(cli && std::holds_alternative<storage::LocalProcess>(*cli));
  EXPECT_EQ(std::get<storage::LocalProcess>(*cli).pid, 42);
  const auto web = storage::parse_owner("boot/123/42/web-7");
  ASSERT_TRUE(web && std::holds_alternative<storage::ServerThread>(*web));
  EXPECT_EQ(std::get<storage::ServerThread>(*web).job, "web-7");
  const auto slurm = storage::parse_owner("slurm:4711@hpc.example.org");
  ASSERT_TRUE(slurm && std::holds_alternative<storage::SlurmJob>(*slurm));
  EXPECT_EQ(std::get<storage::SlurmJob>(*slurm).id, "4711");
  EXPECT_EQ(std::get<storage::SlurmJob>(*slurm).host, "hpc.example.org");
  for (const std::string text : {"boot/123/42/cli", "boot/123/42/web-7", "slurm:4711@hpc.example.org", "slurm:submitting",
                                 "slurm:array@h", "//0/cli"})
    EXPECT_EQ(storage::owner_text(*storage::parse_owner(text)), text);
  EXPECT_EQ(storage::owner_pid("slurm:4711@h"), 0);
  EXPECT_EQ(storage::owner_pid("boot/123/42/cli"), 42);
}

TEST(DesignLease, OwnersReadBackAndNameThisProcess) {
  const storage::ServerThread mine = storage::server_thread("web-3");
  EXPECT_EQ(mine.pid, ::getpid());
  EXPECT_FALSE(mine.boot_id.empty());
  EXPECT_EQ(storage::owner_text(mine), storage::owner_text(storage::server_thread("web-3", ::getpid())));  // stable
  const auto parsed = storage::parse_owner(storage::owner_text(mine));
  ASSERT_TRUE(parsed);
  const auto* back = std::get_if<storage::ServerThread>(&*parsed);
  ASSERT_TRUE(back);
  EXPECT_EQ(storage::owner_text(*back), storage::owner_text(mine));
  EXPECT_EQ(back->job, "web-3");
  EXPECT_NE(storage::server_thread("x", 1).start_time, mine.start_time);  // init started before us
  EXPECT_FALSE(storage::parse_owner("no slashes"));
  EXPECT_FALSE(storage::owner_alive(owner_of(kDeadPid), storage::unix_now(), storage::unix_now(), 0));
}

TEST_F(workflow_designs, UnconfiguredProjectsCannotStartADesign) {
  EXPECT_THROW(storage::Designs(workspace(), project("bare", false)).start(request(me())), storage::NotFound);
  EXPECT_EQ(query("SELECT count(*) FROM designs"), "0");
}

TEST_F(workflow_designs, ASlurmJobOwnsItsDesignUntilTheJobIsSeenToEnd) {
  storage::Projects projects(workspace(), owner());
  projects.create("remote", storage::ClusterConnection{"hpc.example.org", "al", "/scratch/al", ""});
  projects.select("remote");
  projects.set_mission("aac");
  projects.set_budget(10);
  const storage::Project remote = projects.get("remote");
  EXPECT_EQ(remote.cluster->workdir_or_default(), "/scratch/al");
  EXPECT_EQ(remote.cluster->binary_or_default(), "swarmdesign");
  auto request_of_job = request(me());
  request_of_job.owner = storage::owner_text(storage::SlurmJob{"42", "hpc.example.org"});
  storage::Designs designs(workspace(), remote);
  const storage::Design d = designs.start(request_of_job);
  // No process here and no heartbeat: still running, until Slurm says otherwise.
  EXPECT_EQ(designs.latest()->state, storage::DesignState::running);
  storage::ClusterJobs jobs(workspace(), remote);
  jobs.submitted(d.id, "42", "/scratch/al/x/design-1", "{\"ntasks\":4}");
  jobs.observed(d.id, "TIMEOUT", "Slurm job 42 reached its time limit");
  const auto job = jobs.find(d.id);
  ASSERT_TRUE(job);
  EXPECT_EQ(job->job_id, "42");
  EXPECT_EQ(job->slurm_state, "TIMEOUT");
  EXPECT_EQ(job->note, "Slurm job 42 reached its time limit");
  // Another project's jobs are not reachable through this one.
  EXPECT_FALSE(storage::ClusterJobs(workspace(), project("other")).find(d.id));
}

TEST_F(workflow_designs, SeedsKeepAll64Bits) {
  storage::Designs designs(workspace(), project("p"));
  auto wide = request(me());
  wide.seed = 0xFEDCBA9876543210ULL;
  EXPECT_EQ(designs.start(wide).seed, 0xFEDCBA9876543210ULL);
}

}  // namespace
}  // namespace sd::test
