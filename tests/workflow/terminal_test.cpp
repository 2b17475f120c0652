// The password prompt on a real (pseudo-)terminal: nothing typed is ever echoed.
#include <gtest/gtest.h>

#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using workflow_terminal = WorkflowTest;

TEST_F(workflow_terminal, PasswordsAreReadWithoutEchoAndConfirmedAtSignUp) {
  const std::string password = "typed on a terminal";
  const Outcome sign_up = run_swarmdesign_on_terminal(
      {"sign-up", "alice"}, {{"Password for new user alice: ", password}, {"Repeat the password: ", password}},
      environment());
  EXPECT_EQ(sign_up.exit_code, 0) << sign_up.out;
  EXPECT_EQ(sign_up.out.find(password), std::string::npos) << "the password was echoed:\n" << sign_up.out;
  EXPECT_NE(sign_up.out.find("Created user alice"), std::string::npos) << sign_up.out;

  const Outcome sign_in =
      run_swarmdesign_on_terminal({"sign-in", "alice"}, {{"Password for alice: ", password}}, environment());
  EXPECT_EQ(sign_in.exit_code, 0) << sign_in.out;
  EXPECT_EQ(sign_in.out.find(password), std::string::npos) << sign_in.out;
  EXPECT_NE(sign_in.out.find("Signed in as alice"), std::string::npos) << sign_in.out;
}

TEST_F(workflow_terminal, DifferentPasswordsAtSignUpCreateNoAccount) {
  const Outcome outcome = run_swarmdesign_on_terminal(
      {"sign-up", "alice"}, {{"Password for new user alice: ", "first password"}, {"Repeat the password: ", "second password"}},
      environment());
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("swarmdesign: error: the two passwords differ"), std::string::npos) << outcome.out;
  EXPECT_EQ(query("SELECT count(*) FROM users"), "0");
}

}  // namespace
}  // namespace sd::test
