// The bad-input catalogue (issue #34): every user-facing input with malformed variants, each
// refused with one line (or one JSON error) that names what is wrong, the documented status
// (cli.md: 2 misuse, 1 refused work; API.md's HTTP codes), no crash, and not one byte changed
// under the test's folder: the database and its WAL, the session, the projects, the files.
// One TEST per input kind, so ctest runs the kinds in parallel.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>

#include "web/web_client.hpp"
#include "workflow/bad_input/byte_snapshot.hpp"
#include "workflow/bad_input/catalogue.hpp"
#include "workflow/workflow_fixture.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

using namespace bad_input;

std::string shown(const std::vector<std::string>& args) {
  std::string text = "swarmdesign";
  for (const auto& arg : args) text += " [" + (arg.size() > 80 ? arg.substr(0, 80) + "...(" + std::to_string(arg.size()) + ")" : arg) + "]";
  return text;
}

/// What no refusal may print: a crash, an uncaught exception, a sanitizer's report.
void expect_no_crash_output(const std::string& text) {
  for (const char* sign : {"terminate called", "Sanitizer", "runtime error:", "Segmentation", "Aborted", "what():"})
    EXPECT_EQ(text.find(sign), std::string::npos) << "'" << sign << "' in: " << text;
}

class BadInputCatalogue : public WorkflowTest {
 protected:
  void SetUp() override {
    WorkflowTest::SetUp();
    // Commands run in a folder of the scratch space, so a default output folder would show.
    std::filesystem::create_directories(scratch() / "cwd");
    ASSERT_EQ(::chdir((scratch() / "cwd").c_str()), 0);
    sign_up("bob", "another good password");
    sign_in("bob", "another good password");
    run_ok({"new-project", "bobs-project"});
    user_with_active_project("alice", "p1");
    // Above every design space minimum, so run-design cases meet the input they are about.
    run_ok({"set-budget", "5000"});
    run_ok({"set-mission", "aac"});
    inputs_ = {scratch(), scratch() / "files", home() / "users" / "alice" / "projects" / "p1" / "bad-input"};
    write_bad_files(inputs_);
    std::filesystem::create_directories(inputs_.own);
    std::ofstream(inputs_.own / "bad-mission.json") << "not json";
  }
  void TearDown() override {
    ASSERT_EQ(::chdir(std::filesystem::temp_directory_path().c_str()), 0);
    WorkflowTest::TearDown();
  }

  static void report_count(const std::string& kind, std::size_t count) {
    std::cout << "[catalogue] " << kind << ": " << count << " cases\n";
    ::testing::Test::RecordProperty("cases", static_cast<int>(count));
  }

  /// Runs each case, under `timeout` so that a command that wrongly starts work cannot hang.
  void run_cli_cases(const std::string& kind, const std::vector<CliCase>& cases) {
    report_count(kind, cases.size());
    ByteSnapshot before = byte_snapshot(scratch());
    for (const auto& c : cases) {
      SCOPED_TRACE(shown(c.args));
      std::vector<std::string> args{"-s", "KILL", "60", ::sd::test::swarmdesign_binary()};
      args.insert(args.end(), c.args.begin(), c.args.end());
      const Outcome outcome = run_program("timeout", args, c.input, environment());
      expect_error(outcome, c.exit_code, c.phrase);
      expect_no_crash_output(outcome.err);
      if (std::find(c.args.begin(), c.args.end(), "--json") != c.args.end()) {
        EXPECT_EQ(outcome.out, "") << "--json printed a document on a refusal";
      }
      ByteSnapshot after = byte_snapshot(scratch());
      const std::string changed = differences(before, after);
      EXPECT_EQ(changed, "") << "the refused command wrote";
      before = std::move(after);  // one write is reported once
    }
  }

  Inputs inputs_;
};

TEST_F(BadInputCatalogue, CommandArguments) { run_cli_cases("command arguments", argument_cases(inputs_)); }

TEST_F(BadInputCatalogue, FileFormats) { run_cli_cases("file formats", file_cases(inputs_)); }

TEST_F(BadInputCatalogue, StringFormats) { run_cli_cases("string formats", string_cases(inputs_)); }

TEST_F(BadInputCatalogue, HttpRouteBodies) {
  const auto cases = http_cases(inputs_);
  report_count("HTTP route bodies", cases.size());
  RunningServer server(home());
  WebClient alice(server.port());
  ASSERT_TRUE(alice.sign_in("alice", "alice-secret-pw")) << alice.last_refusal();
  const std::string csrf = alice.get("/api/session").body.at("csrf").get<std::string>();
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(std::chrono::seconds(60));
  ByteSnapshot before = byte_snapshot(scratch());
  for (const auto& c : cases) {
    SCOPED_TRACE(c.method + " " + c.path + " " + c.body.substr(0, 120));
    httplib::Headers headers;
    if (c.caller != Caller::SignedOut) headers.emplace("Cookie", alice.cookie());
    if (c.caller == Caller::SignedIn || c.caller == Caller::WrongContentType) headers.emplace("X-CSRF-Token", csrf);
    const std::string type = c.caller == Caller::WrongContentType ? "text/plain" : "application/json";
    const auto result = c.method == "GET" ? client.Get(c.path.c_str(), headers)
                                          : client.Post(c.path.c_str(), headers, c.body, type.c_str());
    ASSERT_TRUE(result) << "no answer: " << httplib::to_string(result.error());
    EXPECT_EQ(result->status, c.status) << result->body;
    const auto body = nlohmann::json::parse(result->body, nullptr, false);
    const bool json_error = body.is_object() && body.contains("error") && body["error"].is_string();
    EXPECT_TRUE(json_error) << "not a JSON error: " << result->body.substr(0, 300);
    const std::string error = json_error ? body["error"].get<std::string>() : "";
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_NE(error.find(c.phrase), std::string::npos) << "expected '" << c.phrase << "' in: " << error;
    ByteSnapshot after = byte_snapshot(scratch());
    EXPECT_EQ(differences(before, after), "") << "the refused request wrote";
    before = std::move(after);
  }
}

}  // namespace
}  // namespace sd::test
