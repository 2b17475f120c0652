// Several swarmdesign processes at once on one home: nobody sees "database is locked",
// the first-run migration happens once, and a contested user name goes to exactly one.
#include <gtest/gtest.h>

#include <thread>

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
