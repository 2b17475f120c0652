// A cancel reaches the MPI backend as it reaches the threads: with the stop flag raised, rank 0
// hands out no more work, collects the chunks already out and throws EvaluationStopped (the
// batch is void, as on threads), and the next batch on the same ranks scores exactly what the
// threads score, no answer of the stopped batch misread. Run under the real mpirun with two
// ranks (CTest test mpi_stop); rank 1 only serves, rank 0 runs the tests.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <vector>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"
#include "missions/catalogue.hpp"
#include "mpi/mpi_evaluator.hpp"
#include "mpi/session.hpp"

namespace sd::mpi {
namespace {

Session* g_session = nullptr;  // this rank's place in the job; null when not run by mpirun

struct Batch {
  explicit Batch(std::size_t runs) : scores(runs) {
    for (std::size_t i = 0; i < runs; ++i) tasks.push_back({&software, 100 + i, 0});
  }
  ControlSoftware software = parse_control_software("--fsm-config --nstates 1 --s0 0 --rwm0 50");
  std::vector<EvaluationTask> tasks;
  std::vector<double> scores;
};

TEST(MpiStop, ARaisedFlagStopsTheBatchOnTheRanksAndTheNextBatchScoresAsOnThreads) {
  if (g_session == nullptr) GTEST_SKIP() << "run by mpirun with two or more ranks (ctest -R mpi_stop)";
  const Mission mission = load_mission("aac");
  ASSERT_FALSE(mission.document.empty()) << "a catalogue mission travels to the ranks as its document";
  MpiEvaluator ranks(*g_session, 1);
  std::atomic<bool> stop{true};
  ranks.stop_when(&stop);

  // Raised before the batch starts: the first chunks are already out to rank 1 when the loop
  // first looks; they are collected, nothing more goes out, and the batch is void.
  Batch stopped(200);
  EXPECT_THROW(ranks.evaluate(mission, stopped.tasks, stopped.scores), EvaluationStopped);

  // Lowered: the next batch on the same ranks is whole and scores as the threads do.
  stop = false;
  Batch next(24);
  ranks.evaluate(mission, next.tasks, next.scores);
  ThreadedEvaluator threads(1);
  Batch reference(24);
  threads.evaluate(mission, reference.tasks, reference.scores);
  EXPECT_EQ(next.scores, reference.scores);
}

TEST(MpiStop, ALoneRankStopsAsTheThreadsDo) {
  if (g_session == nullptr) GTEST_SKIP() << "run by mpirun with two or more ranks (ctest -R mpi_stop)";
  // A mission built in memory has no document for other ranks: rank 0 evaluates it alone, on
  // its threads, and their stop must still be heard.
  Mission mission = load_mission("aac");
  mission.document.clear();
  MpiEvaluator ranks(*g_session, 1);
  std::atomic<bool> stop{true};
  ranks.stop_when(&stop);
  Batch stopped(50);
  EXPECT_THROW(ranks.evaluate(mission, stopped.tasks, stopped.scores), EvaluationStopped);
}

}  // namespace
}  // namespace sd::mpi

int main(int argc, char** argv) {
  const auto session = sd::mpi::Session::join_if_launched(argc, argv);
  if (session && !session->is_root()) return session->serve();
  sd::mpi::g_session = session.get();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();  // then the session tells the other ranks to stop
}
