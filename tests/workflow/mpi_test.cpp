// Designs on MPI ranks, end to end: the real binary under the real `mpirun` (OpenMPI from
// Debian, oversubscribed on this machine), compared with the threaded run of the same seed.
#include <gtest/gtest.h>
#include <unistd.h>

#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

class mpi_runs : public WorkflowTest {
 protected:
  void SetUp() override {
#ifndef SWARMDESIGN_WITH_MPI
    GTEST_SKIP() << "this build has no MPI backend (CMake did not find MPI)";
#endif
    WorkflowTest::SetUp();
    mission_ = write_short_mission(scratch()).string();
  }
  /// `mpirun --oversubscribe -np RANKS swarmdesign args...` in the test's home.
  Outcome mpirun(int ranks, const std::vector<std::string>& args) {
    std::vector<std::string> line{"--oversubscribe", "-np", std::to_string(ranks), ::sd::test::swarmdesign_binary()};
    line.insert(line.end(), args.begin(), args.end());
    Environment env = environment();
    // CI runs as root, which mpirun refuses unless told that it is meant.
    env.set["OMPI_ALLOW_RUN_AS_ROOT"] = "1";
    env.set["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1";
    return run_program("mpirun", line, "", env);
  }
  std::string mpirun_ok(int ranks, const std::vector<std::string>& args) {
    const Outcome outcome = mpirun(ranks, args);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return outcome.out;
  }
  std::vector<std::string> design_args(const std::string& out, int threads) const {
    return {"design", "--mission", mission_, "--budget", "1100", "--seed", "5", "--threads", std::to_string(threads),
            "--out", (scratch() / out).string(), "--json", "--fsm", "--chocolate"};
  }
  std::string mission_;
};

TEST_F(mpi_runs, ADesignOnThreeRanksIsTheThreadedDesignBitForBit) {
  const std::string threaded = run_ok(design_args("threads", 2));
  const std::string ranks = mpirun_ok(3, design_args("ranks", 1));
  ASSERT_FALSE(ranks.empty());
  EXPECT_EQ(design_outcome(ranks), design_outcome(threaded));
  // Every run, in order, with the same cost to the last bit.
  EXPECT_EQ(experiment_log(scratch() / "ranks"), experiment_log(scratch() / "threads"));
  // Hybrid: two ranks of two threads each.
  const std::string hybrid = mpirun_ok(2, design_args("hybrid", 2));
  EXPECT_EQ(experiment_log(scratch() / "hybrid"), experiment_log(scratch() / "threads"));
}

TEST_F(mpi_runs, EachSearchMethodOnTwoRanksIsItsThreadedDesignBitForBit) {
  for (const std::string method : {"random-search", "local-search"}) {
    std::vector<std::string> threads = design_args(method + "-threads", 2), ranks = design_args(method + "-ranks", 1);
    for (auto* args : {&threads, &ranks}) args->insert(args->end(), {"--method", method});
    const std::string threaded = run_ok(threads);
    EXPECT_EQ(design_outcome(mpirun_ok(2, ranks)), design_outcome(threaded)) << method;
    EXPECT_EQ(experiment_log(scratch() / (method + "-ranks")), experiment_log(scratch() / (method + "-threads"))) << method;
  }
}

TEST_F(mpi_runs, EvaluateOnRanksPrintsTheThreadedScores) {
  const std::vector<std::string> args{"evaluate", "--mission", "aac", "--seeds", "1-24", "--threads", "1",
                                      "--fsm-config", "--nstates", "3", "--s0", "14", "--att0", "3.5", "--n0", "1",
                                      "--n0x0", "1", "--c0x0", "13", "--p0x0", "5", "--w0x0", "2", "--s1", "11",
                                      "--s2", "10", "--rwm2", "7"};
  EXPECT_EQ(mpirun_ok(3, args), run_ok(args));
}

TEST_F(mpi_runs, AnMpiDesignKilledMidwayResumesOnRanksOrThreadsToTheSameResult) {
  const std::string threaded = run_ok(design_args("threads", 2));
  const auto folder = scratch() / "killed";
  // Rank 0 SIGKILLs itself right after its 12th checkpoint is durable; mpirun then ends the
  // other ranks, as it does when a node dies or a job is cancelled.
  kill_at_checkpoint(12);
  const Outcome killed = mpirun(3, design_args("killed", 1));
  kill_at_checkpoint(0);
  EXPECT_NE(killed.exit_code, 0) << "the design ended before it could be killed";
  ASSERT_EQ(checkpoint_step(folder), 12);
  // Resumed under MPI and killed again, then finished on threads.
  kill_at_checkpoint(20);
  EXPECT_NE(mpirun(2, {"design", "--resume", folder.string(), "--threads", "1", "--json"}).exit_code, 0);
  kill_at_checkpoint(0);
  ASSERT_EQ(checkpoint_step(folder), 20);
  const std::string resumed = run_ok({"design", "--resume", folder.string(), "--threads", "2", "--json"});
  EXPECT_EQ(design_outcome(resumed), design_outcome(threaded));
  EXPECT_EQ(experiment_log(folder), experiment_log(scratch() / "threads"));
}

TEST_F(mpi_runs, RunDesignRefusesToDetachUnderMpirun) {
  user_with_active_project("ada", "p");
  const Outcome outcome = mpirun(2, {"run-design", "--detach"});
  EXPECT_NE(outcome.exit_code, 0);
  EXPECT_NE(outcome.err.find("--detach cannot be used under mpirun"), std::string::npos) << outcome.err;
}

}  // namespace
}  // namespace sd::test
