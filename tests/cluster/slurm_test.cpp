// Slurm text in both directions: the batch script we write, and the parsers for what sbatch,
// squeue, scontrol and sacct print (samples copied from Slurm 22.05.8).
#include "cluster/slurm.hpp"

#include <gtest/gtest.h>

#include "cluster/support.hpp"

namespace sd::cluster {
namespace {

namespace fs = std::filesystem;

// `scontrol show job -o 4` for a job past its --time (trailing blank as Slurm prints it).
const std::string scontrol_timeout =
    "JobId=4 JobName=to.sh UserId=root(0) GroupId=root(0) MCS_label=N/A Priority=4294901756 Nice=0 Account=(null) "
    "QOS=(null) JobState=TIMEOUT Reason=TimeLimit Dependency=(null) Requeue=1 Restarts=0 BatchFlag=1 Reboot=0 "
    "ExitCode=0:15 RunTime=00:01:22 TimeLimit=00:01:00 TimeMin=N/A SubmitTime=2026-12-02T01:32:06 "
    "EligibleTime=2026-12-02T01:32:06 AccrueTime=2026-12-02T01:32:06 StartTime=2026-12-02T01:32:08 "
    "EndTime=2026-12-02T01:33:30 Deadline=N/A SuspendTime=None SecsPreSuspend=0 LastSchedEval=2026-12-02T01:32:08 "
    "Scheduler=Main Partition=debug AllocNode:Sid=localhost:7816 ReqNodeList=(null) ExcNodeList=(null) NodeList=vm "
    "BatchHost=vm NumNodes=1 NumCPUs=1 NumTasks=1 CPUs/Task=1 ReqB:S:C:T=0:0:*:* TRES=cpu=1,node=1,billing=1 "
    "Socks/Node=* NtasksPerN:B:S:C=0:0:*:* CoreSpec=* MinCPUsNode=1 MinMemoryNode=0 MinTmpDiskNode=0 "
    "Features=(null) DelayBoot=00:00:00 OverSubscribe=OK Contiguous=0 Licenses=(null) Network=(null) "
    "Command=/tmp/sdc-slurm/jobs/to.sh WorkDir=/tmp/sdc-slurm/jobs StdErr=/tmp/sdc-slurm/jobs/slurm-4.out "
    "StdIn=/dev/null StdOut=/tmp/sdc-slurm/jobs/slurm-4.out Power= \n";

const std::string scontrol_failed =
    "JobId=3 JobName=fail.sh UserId=root(0) GroupId=root(0) MCS_label=N/A Priority=4294901757 Nice=0 "
    "Account=(null) QOS=(null) JobState=FAILED Reason=NonZeroExitCode Dependency=(null) Requeue=1 Restarts=0 "
    "BatchFlag=1 Reboot=0 ExitCode=3:0 RunTime=00:00:00 TimeLimit=UNLIMITED TimeMin=N/A Power= ";

// A job name with blanks, and DerivedExitCode, which ends like the ExitCode we want.
const std::string scontrol_odd_name =
    "JobId=1 JobName=my job \"x\" # not comment UserId=root(0) GroupId=root(0) Priority=4294901759 "
    "JobState=COMPLETED Reason=None Dependency=(null) DerivedExitCode=2:0 ExitCode=0:0 Power= ";

TEST(SbatchScript, WritesOnlyTheSettingsGiven) {
  EXPECT_EQ(sbatch_script({}, "echo hi\n"), "#!/bin/bash\necho hi\n");
  JobSettings minimal;
  minimal.job_name = "design-7";
  EXPECT_EQ(sbatch_script(minimal, "run\n"), "#!/bin/bash\n#SBATCH --job-name=design-7\nrun\n");
}

TEST(SbatchScript, WritesEverySettingAndQuotesWhereSbatchWouldSplit) {
  JobSettings full;
  full.job_name = "my \"best\" design # 1";
  full.nodes = 2;
  full.ntasks = 8;
  full.cpus_per_task = 4;
  full.time = "1-12:00:00";
  full.partition = "batch";
  full.account = "swarm.lab";
  full.output = "/scratch/u/runs/out %j.txt";
  full.workdir = "/scratch/u/runs";
  EXPECT_EQ(sbatch_script(full, "srun swarmdesign\n"),
            "#!/bin/bash\n"
            "#SBATCH --job-name=\"my \\\"best\\\" design # 1\"\n"
            "#SBATCH --nodes=2\n"
            "#SBATCH --ntasks=8\n"
            "#SBATCH --cpus-per-task=4\n"
            "#SBATCH --time=1-12:00:00\n"
            "#SBATCH --partition=batch\n"
            "#SBATCH --account=swarm.lab\n"
            "#SBATCH --output=\"/scratch/u/runs/out %j.txt\"\n"
            "#SBATCH --chdir=/scratch/u/runs\n"
            "srun swarmdesign\n");
}

TEST(SbatchScript, AddsTheArrayLine) {
  JobSettings settings;
  settings.output = "runs/%A_%a.out";
  EXPECT_EQ(sbatch_array_script(settings, 10, "x\n"),
            "#!/bin/bash\n#SBATCH --output=runs/%A_%a.out\n#SBATCH --array=0-9\nx\n");
  EXPECT_EQ(sbatch_array_script({}, 1, ""), "#!/bin/bash\n#SBATCH --array=0-0\n");
  EXPECT_THROW(sbatch_array_script({}, 0, ""), ClusterError);
}

TEST(SbatchScript, RefusesWhatSlurmWouldRefuse) {
  JobSettings settings;
  settings.time = "ten minutes";
  EXPECT_THROW(sbatch_script(settings, ""), ClusterError);
  settings = {};
  settings.nodes = 0;
  EXPECT_THROW(sbatch_script(settings, ""), ClusterError);
  settings = {};
  settings.job_name = "two\nlines";
  EXPECT_THROW(sbatch_script(settings, ""), ClusterError);
  settings = {};
  settings.partition = "-p";
  EXPECT_THROW(sbatch_script(settings, ""), ClusterError);
}

TEST(SlurmValues, AcceptsSlurmTimeFormats) {
  for (const char* time : {"", "30", "30:00", "2:30:00", "1-0", "1-12", "1-12:30", "1-12:30:15", "0", "UNLIMITED", "infinite"})
    EXPECT_EQ(time_problem(time), "") << time;
  for (const char* time : {"1:2:3:4", "abc", "1h", "-1", "1-", "1--2", ":30", "1-2:3:4:5", "1 0"})
    EXPECT_NE(time_problem(time), "") << time;
  EXPECT_EQ(time_problem("1h"), "time limit '1h' is not a Slurm time: use M, M:S, H:M:S, D-H, D-H:M or D-H:M:S");
}

TEST(SlurmValues, ChecksPartitionAndAccountNames) {
  EXPECT_EQ(partition_problem("gpu_v100-long.q"), "");
  EXPECT_EQ(partition_problem(""), "");
  EXPECT_EQ(partition_problem("x y"),
            "partition 'x y' is not valid: use letters, digits, '_', '-' or '.', not starting with '-'");
  EXPECT_NE(partition_problem("-x"), "");
  EXPECT_NE(partition_problem("a;b"), "");
  EXPECT_EQ(account_problem("lab-42"), "");
  EXPECT_EQ(account_problem("a/b").rfind("account 'a/b' is not valid", 0), 0u);
}

TEST(ParseJobId, ReadsParsableOutput) {
  EXPECT_EQ(parse_job_id("123\n"), "123");
  EXPECT_EQ(parse_job_id("123;swarmtest\n"), "123");
  EXPECT_EQ(parse_job_id("note from the site\n456\n"), "456");
  EXPECT_THROW(parse_job_id(""), ClusterError);
  EXPECT_THROW(parse_job_id("Submitted batch job 12\n"), ClusterError);
  try {
    parse_job_id("garbage\n");
  } catch (const ClusterError& error) {
    EXPECT_EQ(std::string(error.what()), "sbatch did not print a job id: 'garbage'");
  }
}

TEST(JobStates, NameThemselvesAndKnowWhenTheyAreOver) {
  EXPECT_EQ(to_string(JobState::timeout), "timeout");
  EXPECT_EQ(to_string(JobState::out_of_memory), "out_of_memory");
  for (JobState state : {JobState::pending, JobState::running, JobState::completing, JobState::unknown})
    EXPECT_FALSE(finished(state)) << to_string(state);
  for (JobState state : {JobState::completed, JobState::failed, JobState::cancelled, JobState::timeout,
                         JobState::node_fail, JobState::out_of_memory, JobState::preempted})
    EXPECT_TRUE(finished(state)) << to_string(state);
  EXPECT_EQ(job_state_from_slurm("CG"), JobState::completing);
  EXPECT_EQ(job_state_from_slurm("OUT_OF_MEMORY"), JobState::out_of_memory);
  EXPECT_EQ(job_state_from_slurm("BOOT_FAIL"), JobState::failed);
  EXPECT_EQ(job_state_from_slurm("SOMETHING_NEW"), JobState::unknown);
}

TEST(ParseSqueue, ReadsStateAndReason) {
  JobStatus status = parse_squeue_line("RUNNING|None\n");
  EXPECT_EQ(status.state, JobState::running);
  EXPECT_EQ(status.slurm_state, "RUNNING");
  EXPECT_EQ(status.reason, "");
  status = parse_squeue_line("PENDING|Resources");
  EXPECT_EQ(status.state, JobState::pending);
  EXPECT_EQ(status.reason, "Resources");
  EXPECT_EQ(parse_squeue_line("PENDING|JobHeldUser").reason, "JobHeldUser");
  EXPECT_EQ(parse_squeue_line("COMPLETING|None").state, JobState::completing);
  EXPECT_EQ(parse_squeue_line("CONFIGURING|None").state, JobState::pending);
  EXPECT_EQ(parse_squeue_line("PD|Priority").state, JobState::pending);
  EXPECT_EQ(parse_squeue_line("").state, JobState::unknown);
}

TEST(ParseScontrol, ReadsStateReasonAndExitCode) {
  JobStatus status = parse_scontrol_job(scontrol_timeout);
  EXPECT_EQ(status.state, JobState::timeout);
  EXPECT_EQ(status.slurm_state, "TIMEOUT");
  EXPECT_EQ(status.reason, "TimeLimit");
  EXPECT_EQ(status.exit_code, 0);
  EXPECT_EQ(status.signal, 15);

  status = parse_scontrol_job(scontrol_failed);
  EXPECT_EQ(status.state, JobState::failed);
  EXPECT_EQ(status.reason, "NonZeroExitCode");
  EXPECT_EQ(status.exit_code, 3);
  EXPECT_EQ(status.signal, 0);

  status = parse_scontrol_job(scontrol_odd_name);
  EXPECT_EQ(status.state, JobState::completed);
  EXPECT_EQ(status.reason, "");
  EXPECT_EQ(status.exit_code, 0);
  EXPECT_EQ(parse_scontrol_job("slurm_load_jobs error: Invalid job id specified").state, JobState::unknown);
}

TEST(ParseSacct, ReadsStateWithItsCancellerAndExitCode) {
  JobStatus status = parse_sacct_line("CANCELLED by 0|0:15\n");
  EXPECT_EQ(status.state, JobState::cancelled);
  EXPECT_EQ(status.slurm_state, "CANCELLED");
  EXPECT_EQ(status.reason, "cancelled by uid 0");
  EXPECT_EQ(status.signal, 15);
  status = parse_sacct_line("COMPLETED|0:0");
  EXPECT_EQ(status.state, JobState::completed);
  EXPECT_EQ(status.exit_code, 0);
  EXPECT_EQ(parse_sacct_line("TIMEOUT|0:0").state, JobState::timeout);
  EXPECT_EQ(parse_sacct_line("FAILED|2:0").exit_code, 2);
  EXPECT_EQ(parse_sacct_line("OUT_OF_MEMORY|0:125").state, JobState::out_of_memory);
  EXPECT_EQ(parse_sacct_line("NODE_FAIL|0:0").state, JobState::node_fail);
}

TEST(ArrayTaskIndexes, ExpandsSlurmTaskLists) {
  EXPECT_EQ(array_task_indexes("3"), (std::vector<int>{3}));
  EXPECT_EQ(array_task_indexes("5_3"), (std::vector<int>{3}));
  EXPECT_EQ(array_task_indexes("5_[1-3]"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(array_task_indexes("1-3%2"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(array_task_indexes("[0,4-8:2]"), (std::vector<int>{0, 4, 6, 8}));
  EXPECT_TRUE(array_task_indexes("").empty());
  EXPECT_TRUE(array_task_indexes("x-y").empty());
  EXPECT_TRUE(array_task_indexes("1-5:0").empty());
}

TEST(SlurmCommands, RefuseSomethingThatIsNotAJobId) {
  EXPECT_THROW(job_status(Shell::here(), "1; rm -rf ~"), ClusterError);
  EXPECT_THROW(cancel(Shell::here(), "12 13"), ClusterError);
  EXPECT_THROW(array_status(Shell::here(), ""), ClusterError);
}

TEST(SlurmCommands, SayWhenSlurmIsNotOnThePath) {
  const Shell no_slurm = Shell::here().with_environment({"PATH=/no/such/folder"});
  try {
    submit(no_slurm, "/tmp/job.sh");
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    EXPECT_EQ(std::string(error.what()), "sbatch is not on the path of this machine");
  }
  EXPECT_THROW(job_status(no_slurm, "12"), ClusterError);
  EXPECT_THROW(cancel(no_slurm, "12"), ClusterError);
}

// Stand-ins for squeue, scontrol and sacct (small scripts printing what Slurm 22.05 prints),
// on a PATH without the real ones: they test the order in which job_status asks.
class FakeSlurm {
 public:
  FakeSlurm() {
    fs::create_directories(bin_);
    for (const char* tool : {"mktemp", "cat", "rm"}) {
      const std::string found = first_line(run_command({"sh", "-c", std::string("command -v ") + tool}).out);
      fs::create_symlink(found, bin_ / tool);
    }
  }
  /// `name` prints `out` on stdout, `err` on stderr and exits with `code`.
  void program(const std::string& name, const std::string& out, const std::string& err = "", int code = 0) {
    test_support::write_text(bin_ / name,
                             "#!/bin/sh\nprintf '%s' " + shell_quote(out) + "\nprintf '%s' " + shell_quote(err) +
                                 " >&2\nexit " + std::to_string(code) + "\n",
                             true);
  }
  Shell shell() const { return Shell::here().with_environment({"PATH=" + bin_.string()}); }

 private:
  test_support::TempFolder folder_;
  fs::path bin_ = folder_.path / "bin";
};

const std::string invalid_id = "slurm_load_jobs error: Invalid job id specified\n";

TEST(JobStatusOrder, TakesSqueueFirst) {
  FakeSlurm slurm;
  slurm.program("squeue", "PENDING|Resources\nRUNNING|None\n");  // an array job: the most active task
  slurm.program("scontrol", scontrol_timeout);
  const JobStatus status = job_status(slurm.shell(), "12");
  EXPECT_EQ(status.state, JobState::running);
}

TEST(JobStatusOrder, AsksScontrolWhenSqueueNoLongerListsTheJob) {
  FakeSlurm slurm;
  slurm.program("squeue", "");  // a finished job: nothing, exit 0
  slurm.program("scontrol", scontrol_timeout);
  EXPECT_EQ(job_status(slurm.shell(), "4").state, JobState::timeout);
}

TEST(JobStatusOrder, AsksSacctWhenTheControllerHasForgottenTheJob) {
  FakeSlurm slurm;
  slurm.program("squeue", "", invalid_id, 1);
  slurm.program("scontrol", "", invalid_id, 1);
  slurm.program("sacct", "CANCELLED by 1000|0:15\n");
  const JobStatus status = job_status(slurm.shell(), "4");
  EXPECT_EQ(status.state, JobState::cancelled);
  EXPECT_EQ(status.reason, "cancelled by uid 1000");
}

TEST(JobStatusOrder, SaysSlurmNoLongerKnowsAJobNobodyKnows) {
  FakeSlurm slurm;
  slurm.program("squeue", "", invalid_id, 1);
  slurm.program("scontrol", "", invalid_id, 1);
  slurm.program("sacct", "", "sacct: error: Slurm accounting storage is disabled\n", 1);
  const JobStatus status = job_status(slurm.shell(), "4");
  EXPECT_EQ(status.state, JobState::unknown);
  EXPECT_EQ(status.reason, "Slurm no longer knows job 4");
}

TEST(JobStatusOrder, ThrowsWhenTheControllerCannotBeReached) {
  FakeSlurm slurm;
  slurm.program("squeue", "", "slurm_load_jobs error: Unable to contact slurm controller (connect failure)\n", 1);
  slurm.program("scontrol", scontrol_timeout);  // must not be believed: squeue could not ask
  try {
    job_status(slurm.shell(), "4");
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    EXPECT_EQ(std::string(error.what()),
              "squeue failed on this machine: slurm_load_jobs error: Unable to contact slurm controller (connect failure)");
  }
}

TEST(ArrayStatus, MergesSacctScontrolAndSqueueTheLatestWinning) {
  FakeSlurm slurm;
  slurm.program("sacct", "7_0|COMPLETED|0:0\n7_1|COMPLETED|0:0\n7_[2-5]|PENDING|0:0\n");
  slurm.program("scontrol",
                "JobId=9 ArrayJobId=7 ArrayTaskId=1 JobName=a JobState=FAILED Reason=NonZeroExitCode ExitCode=2:0 Power= \n"
                "JobId=7 ArrayJobId=7 ArrayTaskId=3-5 JobName=a JobState=PENDING Reason=Resources ExitCode=0:0 Power= \n");
  slurm.program("squeue", "7_2|RUNNING|None\n7_3|PENDING|Resources\n7_4|PENDING|Resources\n7_5|PENDING|Priority\n");
  const std::map<int, JobStatus> tasks = array_status(slurm.shell(), "7");
  ASSERT_EQ(tasks.size(), 6u);
  EXPECT_EQ(tasks.at(0).state, JobState::completed);
  EXPECT_EQ(tasks.at(1).state, JobState::failed);  // scontrol knows better than sacct
  EXPECT_EQ(tasks.at(1).exit_code, 2);
  EXPECT_EQ(tasks.at(2).state, JobState::running);
  EXPECT_EQ(tasks.at(5).reason, "Priority");
}

}  // namespace
}  // namespace sd::cluster
