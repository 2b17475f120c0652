// Several swarmdesign processes at once on one home: nobody sees "database is locked",
// the first-run migration happens once, and a contested user name goes to exactly one.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "storage/sqlite.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using workflow_concurrency = WorkflowTest;

std::vector<Outcome> run_together(const std::vector<std::vector<std::string>>& commands, const std::string& input,
                                  const Environment& environment) {
  std::vector<Outcome> outcomes(commands.size());
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < commands.size(); ++i)
    threads.emplace_back([&, i] { outcomes[i] = run_swarmdesign(commands[i], input, environment); });
  for (auto& thread : threads) thread.join();
  return outcomes;
}

TEST_F(workflow_concurrency, SimultaneousSignUpsOnAFreshHomeAllSucceed) {
  const auto outcomes = run_together({{"sign-up", "u1", "--password-stdin"},
                                      {"sign-up", "u2", "--password-stdin"},
                                      {"sign-up", "u3", "--password-stdin"},
                                      {"sign-up", "u4", "--password-stdin"}},
                                     "correct horse battery\n", environment());
  for (const auto& outcome : outcomes) EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(query("SELECT count(*) FROM users"), "4");
}

// The deterministic core of the test above. A new database file is in rollback-journal mode
// until its first opener switches it to WAL, and that switch turns a read lock into a write
// lock: SQLite then returns "database is locked" at once instead of calling the busy
// handler. Opening must wait for the other writer like any other statement does.
TEST_F(workflow_concurrency, OpeningAFreshDatabaseWaitsForAWriterInsteadOfFailing) {
  const auto path = scratch() / "fresh.db";
  sqlite3* writer = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &writer), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(writer, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr), SQLITE_OK);
  std::atomic<bool> releasing = false;
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    releasing = true;  // before COMMIT: the opener cannot get the lock earlier than this
    sqlite3_exec(writer, "COMMIT", nullptr, nullptr, nullptr);
  });
  EXPECT_NO_THROW(storage::Database opened(path));
  EXPECT_TRUE(releasing) << "Database() returned before the writer let go of its lock";
  release.join();
  sqlite3_close(writer);
  storage::Database reopened(path, false);
  auto mode = reopened.prepare("PRAGMA journal_mode");
  ASSERT_TRUE(mode.step());
  EXPECT_EQ(mode.text(0), "wal");
}

TEST_F(workflow_concurrency, AContestedUserNameGoesToExactlyOneSignUp) {
  run_ok({"show-users"});  // the home exists; the race is on the name alone
  const auto outcomes = run_together({{"sign-up", "alice", "--password-stdin"},
                                      {"sign-up", "alice", "--password-stdin"},
                                      {"sign-up", "Alice", "--password-stdin"}},
                                     "correct horse battery\n", environment());
  int winners = 0;
  for (const auto& outcome : outcomes) {
    if (outcome.exit_code == 0) {
      ++winners;
    } else {
      expect_error(outcome, 1, "already taken");
    }
  }
  EXPECT_EQ(winners, 1);
  EXPECT_EQ(query("SELECT count(*) FROM users"), "1");
}

}  // namespace
}  // namespace sd::test
