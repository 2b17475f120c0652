#pragma once
// A fresh SwarmDesign home per test, helpers to run commands in it, and a snapshot of
// everything a refused command must leave untouched.
#include <gtest/gtest.h>

#include <filesystem>
#include <cstdint>
#include <string>
#include <vector>

#include "workflow/swarmdesign_process.hpp"

namespace sd::test {

class WorkflowTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  /// swarmdesign with SWARMDESIGN_HOME = home().
  Outcome run(const std::vector<std::string>& args, const std::string& input = "");
  /// Runs and expects exit 0, returning stdout.
  std::string run_ok(const std::vector<std::string>& args, const std::string& input = "");

  void sign_up(const std::string& user, const std::string& password);
  void sign_in(const std::string& user, const std::string& password);
  /// sign-up, sign-in, new-project and select-project in one go.
  void user_with_active_project(const std::string& user, const std::string& project);

  const std::filesystem::path& home() const { return home_; }
  const std::filesystem::path& scratch() const { return scratch_; }
  std::filesystem::path database() const { return home_ / "swarmdesign.db"; }
  Environment environment() const;
  /// The next commands run with SWARMDESIGN_KILL_AT_CHECKPOINT=step: a design SIGKILLs itself
  /// right after saving that checkpoint (0: no longer).
  void kill_at_checkpoint(std::int64_t step) { kill_at_checkpoint_ = step; }

  /// Every table's rows, the files under the home (but the database's own) and the
  /// session token: what a refused command must not change.
  std::string snapshot() const;
  /// One value of a query on the database, as text.
  std::string query(const std::string& sql) const;

 private:
  std::filesystem::path scratch_;
  std::filesystem::path home_;
  std::int64_t kill_at_checkpoint_ = 0;
};

/// Expects the one-line error of the command contract with this exit code.
void expect_error(const Outcome& outcome, int exit_code, const std::string& message_part);

}  // namespace sd::test
