// check_cluster on this machine with a PATH built for the test: a stand-in SwarmDesign
// binary that prints its version, and no Slurm commands.
#include "cluster/cluster_check.hpp"

#include <gtest/gtest.h>

#include "cluster/support.hpp"

namespace sd::cluster {
namespace {

namespace fs = std::filesystem;
using test_support::TempFolder;

const std::string our_version = "swarmdesign 0.1.0 (results version 7)\n";

// A folder holding the few tools the checks use, so that PATH can leave Slurm out even
// where it is installed in /usr/bin.
struct NoSlurmMachine {
  TempFolder folder;
  fs::path tools = folder.path / "bin";
  std::string binary = (folder.path / "bin/swarmdesign").string();
  Shell shell = Shell::here();

  explicit NoSlurmMachine(const std::string& version_line) {
    fs::create_directories(tools);
    for (const char* tool : {"sh", "mkdir", "touch", "rm"}) {
      const std::string found = first_line(run_command({"sh", "-c", std::string("command -v ") + tool}).out);
      fs::create_symlink(found, tools / tool);
    }
    test_support::write_text(binary, "#!/bin/sh\necho '" + version_line + "'\necho 'more lines'\n", true);
    shell = Shell::here().with_environment({"PATH=" + tools.string()});
  }
};

const Check& find(const std::vector<Check>& checks, const std::string& what) {
  for (const Check& check : checks)
    if (check.what == what) return check;
  throw std::runtime_error("no check " + what);
}

TEST(ClusterCheck, ReportsMissingSlurmCommandsAndWhatWorks) {
  const NoSlurmMachine machine("swarmdesign 0.1.0 (results version 7)");
  const std::string workdir = (machine.folder.path / "work/runs").string();
  const std::vector<Check> checks = check_cluster(machine.shell, machine.binary, our_version, workdir);

  std::vector<std::string> order;
  for (const Check& check : checks) order.push_back(check.what);
  EXPECT_EQ(order, (std::vector<std::string>{"connection", "sbatch", "squeue", "scancel", "swarmdesign", "working folder", "mpirun"}));

  EXPECT_TRUE(find(checks, "connection").ok);
  const Check& sbatch = find(checks, "sbatch");
  EXPECT_FALSE(sbatch.ok);
  EXPECT_EQ(sbatch.detail, "sbatch is not on the path of this machine");
  EXPECT_FALSE(find(checks, "squeue").ok);
  EXPECT_FALSE(find(checks, "scancel").ok);
  EXPECT_TRUE(find(checks, "swarmdesign").ok) << find(checks, "swarmdesign").detail;
  EXPECT_TRUE(find(checks, "working folder").ok) << find(checks, "working folder").detail;
  EXPECT_TRUE(fs::is_directory(workdir));
  EXPECT_TRUE(fs::is_empty(workdir));  // the probe file is gone
  const Check& mpirun = find(checks, "mpirun");
  EXPECT_TRUE(mpirun.ok);
  EXPECT_EQ(mpirun.detail, "no mpirun on the path: each job runs one process");
}

TEST(ClusterCheck, FindsSlurmCommandsOnThePath) {
  const NoSlurmMachine machine("swarmdesign 0.1.0 (results version 7)");
  test_support::write_text(machine.tools / "sbatch", "#!/bin/sh\n", true);
  const std::vector<Check> checks = check_cluster(machine.shell, machine.binary, our_version, machine.folder.path.string());
  EXPECT_TRUE(find(checks, "sbatch").ok);
  EXPECT_EQ(find(checks, "sbatch").detail, (machine.tools / "sbatch").string());
}

TEST(ClusterCheck, ReportsAnotherVersionOfTheBinaryWithBothLines) {
  const NoSlurmMachine machine("swarmdesign 0.0.9 (results version 6)");
  const Check binary = find(check_cluster(machine.shell, machine.binary, our_version, machine.folder.path.string()), "swarmdesign");
  EXPECT_FALSE(binary.ok);
  EXPECT_EQ(binary.detail, machine.binary +
                               " on this machine is 'swarmdesign 0.0.9 (results version 6)', this one is "
                               "'swarmdesign 0.1.0 (results version 7)'");
}

TEST(ClusterCheck, ReportsAMissingBinaryAndAFolderThatCannotBeWritten) {
  const NoSlurmMachine machine("unused");
  test_support::write_text(machine.folder.path / "a-file", "x");
  const std::vector<Check> checks = check_cluster(machine.shell, (machine.folder.path / "nothing-here").string(),
                                                  our_version, (machine.folder.path / "a-file/work").string());
  const Check& binary = find(checks, "swarmdesign");
  EXPECT_FALSE(binary.ok);
  EXPECT_NE(binary.detail.find("nothing-here --version failed on this machine: "), std::string::npos) << binary.detail;
  const Check& workdir = find(checks, "working folder");
  EXPECT_FALSE(workdir.ok);
  EXPECT_EQ(workdir.detail.rfind("cannot write in " + (machine.folder.path / "a-file/work").string() + " on this machine: ", 0), 0u)
      << workdir.detail;
  for (const Check& check : checks) EXPECT_EQ(check.detail.find('\n'), std::string::npos) << check.detail;
}

TEST(ClusterCheck, StopsAtAHostItCannotReach) {
  const test_support::ScopedEnv ssh("SWARMDESIGN_SSH", "/no/such/ssh");
  const std::vector<Check> checks = check_cluster(Shell::for_cluster("127.0.0.1", "nobody"), "swarmdesign", our_version, "~/runs");
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks[0].what, "connection");
  EXPECT_FALSE(checks[0].ok);
  EXPECT_EQ(checks[0].detail.rfind("cannot reach nobody@127.0.0.1 over ssh: ", 0), 0u) << checks[0].detail;
}

TEST(ClusterCheck, WorksOverTheSshRoad) {
  TempFolder folder;
  const Shell remote = test_support::fake_ssh_shell(folder.path);
  const std::vector<Check> checks = check_cluster(remote, "", our_version, (folder.path / "w").string());
  EXPECT_TRUE(find(checks, "connection").ok);
  EXPECT_EQ(find(checks, "connection").detail, "ssh to " + test_support::current_user() + "@127.0.0.1 works");
  EXPECT_FALSE(find(checks, "swarmdesign").ok);  // none given
  EXPECT_TRUE(find(checks, "working folder").ok);
}

}  // namespace
}  // namespace sd::cluster
