// run_command on real programs: output, exit codes, stdin, large outputs without deadlock,
// timeouts that kill, and a child that stops reading its stdin.
#include "cluster/process.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "cluster/support.hpp"

namespace sd::cluster {
namespace {

using test_support::read_text;
using test_support::TempFolder;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

TEST(RunCommand, CapturesStdoutStderrAndTheExitCode) {
  const CommandResult result = run_command({"sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_TRUE(result.started());
  EXPECT_EQ(result.out, "out\n");
  EXPECT_EQ(result.err, "err\n");
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_FALSE(result.timed_out);
}

TEST(RunCommand, PassesArgumentsAsTheyAre) {
  const CommandResult result = run_command({"printf", "%s|", "a b", "$HOME", "'q'", ""});
  EXPECT_EQ(result.out, "a b|$HOME|'q'||");
}

TEST(RunCommand, WritesTheInputToStdin) {
  const std::string input = std::string("hello\nworld\0with a zero byte", 28);
  const CommandResult result = run_command({"cat"}, input);
  EXPECT_EQ(result.out, input);
  EXPECT_EQ(result.exit_code, 0);
}

TEST(RunCommand, ReadsSeveralMegabytesFromBothStreamsWithoutDeadlock) {
  const CommandResult result = run_command({"sh", "-c", "head -c 3000000 /dev/zero >&2; head -c 5000000 /dev/zero"});
  EXPECT_EQ(result.out.size(), 5000000u);
  EXPECT_EQ(result.err.size(), 3000000u);
  EXPECT_EQ(result.exit_code, 0);
}

TEST(RunCommand, FeedsAndReadsLargeDataAtOnce) {
  std::string input(6000000, 'x');
  for (std::size_t i = 0; i < input.size(); i += 997) input[i] = static_cast<char>(i % 256);
  const CommandResult result = run_command({"cat"}, input);
  EXPECT_EQ(result.out, input);
}

TEST(RunCommand, SurvivesAChildThatClosesItsStdinEarly) {
  const CommandResult result = run_command({"sh", "-c", "exec 0<&-; sleep 0.2; echo done"}, std::string(10000000, 'x'));
  EXPECT_EQ(result.out, "done\n");
  EXPECT_EQ(result.exit_code, 0);
  const CommandResult second = run_command({"true"}, std::string(10000000, 'x'));  // never reads at all
  EXPECT_EQ(second.exit_code, 0);
}

TEST(RunCommand, ReportsAMissingProgramAs127) {
  const CommandResult result = run_command({"swarmdesign-no-such-program"});
  EXPECT_FALSE(result.started());
  EXPECT_EQ(result.exit_code, 127);
  EXPECT_NE(result.start_error.find("swarmdesign-no-such-program"), std::string::npos);
  EXPECT_EQ(run_command({"/no/such/folder/program"}).exit_code, 127);
  EXPECT_EQ(run_command({}).exit_code, 127);
}

TEST(RunCommand, ReportsAFileThatCannotRunAs126) {
  TempFolder folder;
  test_support::write_text(folder.path / "data.txt", "not a program");
  const CommandResult result = run_command({(folder.path / "data.txt").string()});
  EXPECT_FALSE(result.started());
  EXPECT_EQ(result.exit_code, 126);
}

TEST(RunCommand, KillsAProgramThatOutlivesItsTimeout) {
  const auto start = Clock::now();
  const CommandResult result = run_command({"sleep", "10"}, "", 1);
  EXPECT_TRUE(result.timed_out);
  EXPECT_EQ(result.exit_code, 128 + 9);
  EXPECT_LT(seconds_since(start), 3.0);
}

TEST(RunCommand, KillsTheChildrenOfATimedOutProgramToo) {
  const auto start = Clock::now();
  // The background sleep holds stdout open: only killing the whole group ends the wait.
  const CommandResult result = run_command({"sh", "-c", "sleep 10 & sleep 10"}, "", 1);
  EXPECT_TRUE(result.timed_out);
  EXPECT_LT(seconds_since(start), 3.0);
}

TEST(RunCommand, ReturnsWhenTheProgramExitsEvenIfABackgroundChildKeepsItsOutputOpen) {
  const auto start = Clock::now();
  const CommandResult result = run_command({"sh", "-c", "sleep 3 & echo started"}, "", 10);
  EXPECT_FALSE(result.timed_out);
  EXPECT_EQ(result.out, "started\n");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_LT(seconds_since(start), 2.0);
}

TEST(RunCommand, ReportsASignalAs128PlusItsNumber) {
  EXPECT_EQ(run_command({"sh", "-c", "kill -TERM $$"}).exit_code, 128 + 15);
}

TEST(RunCommand, AddsAndReplacesEnvironmentVariables) {
  const CommandResult result =
      run_command({"sh", "-c", "echo \"$SD_CLUSTER_TEST|$HOME\""}, "", 10, {"SD_CLUSTER_TEST=a b", "HOME=/elsewhere"});
  EXPECT_EQ(result.out, "a b|/elsewhere\n");
}

TEST(RunCommand, LooksTheProgramUpOnThePathItWillSee) {
  EXPECT_EQ(run_command({"ls"}, "", 10, {"PATH=/no/such/folder"}).exit_code, 127);
  EXPECT_EQ(run_command({"ls", "/"}, "", 10, {"PATH=/no/such/folder:/bin:/usr/bin"}).exit_code, 0);
}

TEST(RunCommand, CanSendStdoutToAFile) {
  TempFolder folder;
  CommandOptions options;
  options.stdout_file = folder.path / "out.bin";
  options.input = std::string("a\0b\xff", 4);
  const CommandResult result = run_command({"cat"}, options);
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_TRUE(result.out.empty());
  EXPECT_EQ(read_text(options.stdout_file), options.input);
}

TEST(FirstLine, SkipsBlankLinesAndLineEndings) {
  EXPECT_EQ(first_line("\n  \nssh: connect refused\r\nmore\n"), "ssh: connect refused");
  EXPECT_EQ(first_line(""), "");
  EXPECT_EQ(first_line("only"), "only");
}

}  // namespace
}  // namespace sd::cluster
