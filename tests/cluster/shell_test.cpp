// Shell: quoting that survives sh, the local-or-ssh decision, and the errors of an ssh that
// cannot reach its host (a real ssh against a port where nothing listens).
#include "cluster/shell.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <climits>

#include "cluster/support.hpp"

namespace sd::cluster {
namespace {

using test_support::current_user;
using test_support::ScopedEnv;
using test_support::TempFolder;

std::string host_name() {
  char name[HOST_NAME_MAX + 1] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

TEST(ShellQuote, RoundTripsNastyTextThroughSh) {
  for (const std::string text : {"", "plain", "it's", "a b  c", "$HOME `id` $(id) ${x}", "line1\nline2\n",
                                 "back\\slash", "\"double\"", "'", "''", "*?[a]", "-n", "tab\there", "; rm -rf /tmp/x &"}) {
    const CommandResult result = run_command({"sh", "-c", "printf %s " + shell_quote(text)});
    EXPECT_EQ(result.out, text) << shell_quote(text);
  }
}

TEST(ShellPath, LetsTheShellExpandALeadingTilde) {
  EXPECT_EQ(shell_path("/a b/c"), "'/a b/c'");
  EXPECT_EQ(shell_path("~/runs/x y"), "\"$HOME\"/'runs/x y'");
  EXPECT_EQ(shell_path("~"), "\"$HOME\"");
  EXPECT_EQ(shell_path("a/~/b"), "'a/~/b'");
  const CommandResult result = run_command({"sh", "-c", "printf %s " + shell_path("~/runs/x y")}, "", 10, {"HOME=/home/with space"});
  EXPECT_EQ(result.out, "/home/with space/runs/x y");
}

TEST(Shell, IsLocalForThisMachineAndTheCurrentUser) {
  const std::string user = current_user();
  EXPECT_TRUE(Shell::for_cluster("localhost", user).local());
  EXPECT_TRUE(Shell::for_cluster("localhost", "").local());
  EXPECT_TRUE(Shell::for_cluster(host_name(), user).local());
  EXPECT_TRUE(Shell::for_cluster(host_name().substr(0, host_name().find('.')), user).local());
  EXPECT_EQ(Shell::for_cluster("localhost", user).describe(), "this machine");
}

TEST(Shell, GoesOverSshForAnyOtherHostOrUser) {
  const Shell by_address = Shell::for_cluster("127.0.0.1", current_user());
  EXPECT_FALSE(by_address.local());
  EXPECT_EQ(by_address.describe(), current_user() + "@127.0.0.1 (ssh)");
  EXPECT_FALSE(Shell::for_cluster("localhost", current_user() + "x").local());
  EXPECT_FALSE(Shell::for_cluster("login.cluster.example.org", current_user()).local());
  EXPECT_EQ(Shell::for_cluster("login.example.org", "").describe(), "login.example.org (ssh)");
}

TEST(Shell, RefusesHostsAndUsersThatSshWouldReadAsOptions) {
  EXPECT_THROW(Shell::for_cluster("-oProxyCommand=touch /tmp/x", "u"), ClusterError);
  EXPECT_THROW(Shell::for_cluster("host", "-lroot"), ClusterError);
  EXPECT_THROW(Shell::for_cluster("", "u"), ClusterError);
  EXPECT_THROW(Shell::for_cluster("a b", "u"), ClusterError);
}

TEST(Shell, BuildsTheSshCommandFromSwarmdesignSsh) {
  const ScopedEnv ssh("SWARMDESIGN_SSH", "  ssh  -p 2222 ");
  const std::vector<std::string> expected{"ssh", "-p", "2222", "-o", "BatchMode=yes", "-o", "ConnectTimeout=10",
                                          "alice@login", "--", "echo 'a b'"};
  EXPECT_EQ(Shell::for_cluster("login", "alice").command_for("echo 'a b'"), expected);
  EXPECT_EQ(Shell::here().command_for("true"), (std::vector<std::string>{"/bin/sh", "-c", "true"}));
}

TEST(Shell, HereRunsShCommandLines) {
  const Shell here = Shell::here();
  EXPECT_TRUE(here.local());
  EXPECT_EQ(here.run("echo $((1 + 2))").out, "3\n");
  EXPECT_EQ(here.run("tr a-z A-Z", "shout").out, "SHOUT");
  EXPECT_EQ(here.run_checked("exit 7").exit_code, 7);  // the script's own failure is returned
  EXPECT_EQ(here.with_environment({"SD_CLUSTER_TEST=set"}).run("echo $SD_CLUSTER_TEST").out, "set\n");
}

TEST(Shell, ThrowsWhenTheCommandDoesNotAnswerInTime) {
  try {
    Shell::here().run_checked("sleep 5", "", 1);
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    EXPECT_EQ(std::string(error.what()), "this machine did not answer within 1 s");
  }
}

TEST(Shell, PassesTheScriptThroughSshAsOneCommandLine) {
  TempFolder folder;
  const Shell remote = test_support::fake_ssh_shell(folder.path);
  EXPECT_FALSE(remote.local());
  const CommandResult result = remote.run_checked("printf '%s|' \"a  b\" 'it'\\''s'; echo; cat", "input");
  EXPECT_EQ(result.out, "a  b|it's|\ninput");
}

TEST(Shell, ReportsAHostItCannotReachOnOneLine) {
  // A real ssh to a port where nothing listens: exit 255, "Connection refused".
  const ScopedEnv ssh("SWARMDESIGN_SSH", "ssh -o ConnectTimeout=2 -o StrictHostKeyChecking=no -p 1");
  const Shell remote = Shell::for_cluster("127.0.0.1", "nobody");
  try {
    remote.run_checked("true", "", 20);
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("cannot reach nobody@127.0.0.1 over ssh: ", 0), 0u) << message;
    EXPECT_NE(message.find("refused"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Shell, ReportsAMissingSshProgram) {
  const ScopedEnv ssh("SWARMDESIGN_SSH", "/no/such/ssh");
  try {
    Shell::for_cluster("127.0.0.1", "nobody").run_checked("true");
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cannot reach nobody@127.0.0.1 over ssh: cannot run /no/such/ssh", 0), 0u)
        << error.what();
  }
}

}  // namespace
}  // namespace sd::cluster
