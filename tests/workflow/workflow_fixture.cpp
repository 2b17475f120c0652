#include "workflow/workflow_fixture.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "storage/sqlite.hpp"

namespace sd::test {

void WorkflowTest::SetUp() {
  std::string pattern = (std::filesystem::temp_directory_path() / "swarmdesign-workflow-XXXXXX").string();
  ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
  scratch_ = pattern;
  home_ = scratch_ / "home";
}

void WorkflowTest::TearDown() {
  std::error_code ignored;
  std::filesystem::remove_all(scratch_, ignored);
}

Environment WorkflowTest::environment() const {
  // HOME points into the scratch folder too, so nothing can touch the real one.
  Environment environment{{{"SWARMDESIGN_HOME", home_.string()}, {"HOME", (scratch_ / "user-home").string()}},
                          {"XDG_DATA_HOME", "SWARMDESIGN_KILL_AT_CHECKPOINT"}};
  if (kill_at_checkpoint_ > 0) {
    environment.set["SWARMDESIGN_KILL_AT_CHECKPOINT"] = std::to_string(kill_at_checkpoint_);
    environment.unset.pop_back();
  }
  return environment;
}

Outcome WorkflowTest::run(const std::vector<std::string>& args, const std::string& input) {
  return run_swarmdesign(args, input, environment());
}

std::string WorkflowTest::run_ok(const std::vector<std::string>& args, const std::string& input) {
  const Outcome outcome = run(args, input);
  std::string command;
  for (const auto& arg : args) command += " " + arg;
  EXPECT_EQ(outcome.exit_code, 0) << "swarmdesign" << command << "\nstdout: " << outcome.out
                                  << "\nstderr: " << outcome.err;
  return outcome.out;
}

void WorkflowTest::sign_up(const std::string& user, const std::string& password) {
  run_ok({"sign-up", user, "--password-stdin"}, password + "\n");
}

void WorkflowTest::sign_in(const std::string& user, const std::string& password) {
  run_ok({"sign-in", user, "--password-stdin"}, password + "\n");
}

void WorkflowTest::user_with_active_project(const std::string& user, const std::string& project) {
  sign_up(user, user + "-secret-pw");
  sign_in(user, user + "-secret-pw");
  run_ok({"new-project", project});
  run_ok({"select-project", project});
}

std::string WorkflowTest::query(const std::string& sql) const {
  storage::Database db(database(), false);
  auto statement = db.prepare(sql);
  if (!statement.step()) return "<no row>";
  return statement.is_null(0) ? "<null>" : statement.text(0);
}

std::string WorkflowTest::snapshot() const {
  std::ostringstream text;
  {
    storage::Database db(database(), false);
    auto version = db.prepare("PRAGMA user_version");
    version.step();
    text << "schema " << version.integer(0) << '\n';
    auto tables = db.prepare("SELECT name, sql FROM sqlite_master WHERE type = 'table' ORDER BY name");
    while (tables.step()) {
      const std::string table = tables.text(0);
      text << "table " << table << '\n' << tables.text(1) << '\n';
      // The count of failed sign-ins is the one thing a refused sign-in must change.
      if (table == "sign_in_failures") continue;
      auto rows = db.prepare("SELECT * FROM \"" + table + "\" ORDER BY rowid");
      const int columns = rows.column_count();
      while (rows.step()) {
        for (int c = 0; c < columns; ++c) text << (rows.is_null(c) ? "<null>" : rows.blob(c)) << '|';
        text << '\n';
      }
    }
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(home_)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("swarmdesign.db", 0) == 0) continue;
    files.push_back(std::filesystem::relative(entry.path(), home_).string());
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) text << "file " << file << '\n';
  std::ifstream session(home_ / "session");
  text << "session " << std::string(std::istreambuf_iterator<char>(session), {}) << '\n';
  return text.str();
}

void expect_error(const Outcome& outcome, int exit_code, const std::string& message_part) {
  EXPECT_EQ(outcome.exit_code, exit_code) << "stderr: " << outcome.err;
  EXPECT_EQ(outcome.err.rfind("swarmdesign: error: ", 0), 0u) << outcome.err;
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << "one line expected: " << outcome.err;
  EXPECT_NE(outcome.err.find(message_part), std::string::npos)
      << "expected '" << message_part << "' in: " << outcome.err;
}

}  // namespace sd::test
