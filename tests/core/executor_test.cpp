// The process's thread pool: results by index whatever the workers, slots that no two threads
// share, errors that reach the caller, and jobs that share the pool instead of growing it.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/executor.hpp"

namespace sd {
namespace {

TEST(Executor, EveryIndexRunsOnceAndSlotsStayBelowTheWorkersAsked) {
  Executor pool;
  for (unsigned workers : {1u, 2u, 3u, 8u}) {
    std::vector<int> runs(1000, 0);
    std::vector<std::atomic<int>> busy(workers);
    std::atomic<bool> shared_slot{false};
    pool.run(runs.size(), workers, [&](std::size_t i, unsigned slot) {
      ASSERT_LT(slot, workers);
      if (busy[slot].fetch_add(1) != 0) shared_slot = true;
      runs[i] += 1;
      busy[slot].fetch_sub(1);
    });
    EXPECT_EQ(std::count(runs.begin(), runs.end(), 1), 1000) << workers << " workers";
    EXPECT_FALSE(shared_slot) << "two threads held one slot at once";
  }
  EXPECT_EQ(pool.size(), 8u);  // the largest number asked, not the sum
}

TEST(Executor, TheFirstErrorReachesTheCallerAndStopsTheBatch) {
  Executor pool;
  const auto failing = [](std::atomic<int>& ran) {
    return [&ran](std::size_t i, unsigned) {
      ++ran;
      if (i == 3) throw std::runtime_error("run 3 failed");
    };
  };
  std::atomic<int> ran{0};
  EXPECT_THROW(pool.run(10000, 1, failing(ran)), std::runtime_error);
  EXPECT_EQ(ran.load(), 4);  // one worker: indices 0..3, then nothing more is handed out
  std::atomic<int> ran_on_two{0};
  EXPECT_THROW(pool.run(10000, 2, failing(ran_on_two)), std::runtime_error);
  // The pool is still usable afterwards.
  std::atomic<int> after{0};
  pool.run(100, 2, [&](std::size_t, unsigned) { ++after; });
  EXPECT_EQ(after.load(), 100);
}

TEST(Executor, JobsFromSeveralThreadsShareThePool) {
  Executor pool;
  std::vector<std::thread> jobs;
  std::vector<long long> sums(4, 0);
  for (int j = 0; j < 4; ++j)
    jobs.emplace_back([&, j] {
      std::vector<long long> values(500);
      pool.run(values.size(), 2, [&](std::size_t i, unsigned) { values[i] = static_cast<long long>(i) * (j + 1); });
      for (long long v : values) sums[j] += v;
    });
  for (auto& job : jobs) job.join();
  for (int j = 0; j < 4; ++j) EXPECT_EQ(sums[j], 124750LL * (j + 1));
  EXPECT_EQ(pool.size(), 2u);
}

TEST(Executor, AJobStartedInsideThePoolRunsInline) {
  Executor pool;
  std::atomic<int> inner{0};
  pool.run(4, 2, [&](std::size_t, unsigned) {
    Executor::shared().run(3, 2, [&](std::size_t, unsigned slot) {
      EXPECT_EQ(slot, 0u);
      ++inner;
    });
  });
  EXPECT_EQ(inner.load(), 12);
}

TEST(Executor, ZeroThreadsMeansOnePerCore) {
  EXPECT_EQ(resolve_threads(0u), std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(resolve_threads(3u), 3u);
  EXPECT_EQ(resolve_threads(-1), resolve_threads(0));
}

TEST(Executor, WorkersTakeTheNicenessSetForThemBeforeTheirNextBatch) {
  const int mine = Executor::thread_niceness();
  const int lower = std::min(mine + 5, 19);
  Executor pool;
  const auto niceness_seen = [&] {
    std::vector<int> seen(64, -100);
    pool.run(seen.size(), 2, [&](std::size_t i, unsigned) { seen[i] = Executor::thread_niceness(); });
    return std::set<int>(seen.begin(), seen.end());
  };
  EXPECT_EQ(niceness_seen(), std::set<int>{mine}) << "a new pool runs as its creator does";
  pool.set_worker_niceness(lower);  // threads that exist already take it too
  EXPECT_EQ(niceness_seen(), std::set<int>{lower});
  EXPECT_EQ(Executor::thread_niceness(), mine) << "the caller's own thread is left alone";
}

}  // namespace
}  // namespace sd
