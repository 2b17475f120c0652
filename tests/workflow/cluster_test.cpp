// Cluster projects end to end against real services: a one-node Slurm from Debian's packages
// (munge, slurmctld, slurmd) and an sshd on 127.0.0.1 with a key made for the test, both
// started by tests/cluster/services/ and stopped at the end. The project's designs are
// submitted through the local path (this machine is the login node) and over ssh, followed by
// status to the end, cancelled with stop-design, refused by sbatch, cut by their time limit;
// and the web app's Start and Stop of a cluster project go to Slurm the same way.
#include <gtest/gtest.h>
#include <pwd.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/workflow_fixture.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;

const std::string kServices = std::string(::sd::test::source_dir()) + "/tests/cluster/services/";

/// "export NAME=value" or "export NAME=\"value\"" as printed by the services' start.
std::pair<std::string, std::string> exported(const std::string& line) {
  const auto eq = line.find('=');
  std::string value = line.substr(eq + 1);
  while (!value.empty() && (value.back() == '\n' || value.back() == '"')) value.pop_back();
  if (!value.empty() && value.front() == '"') value.erase(0, 1);
  return {line.substr(7, eq - 7), value};
}

class cluster_projects : public WorkflowTest {
 protected:
  static void SetUpTestSuite() {
    std::string pattern = (std::filesystem::temp_directory_path() / "swarmdesign-services-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    services_ = pattern;
    for (const char* service : {"slurm", "sshd"}) {
      const Outcome started = run_program(kServices + service + ".sh", {"start", (services_ / service).string()}, "", {});
      ASSERT_EQ(started.exit_code, 0) << service << " did not start:\n" << started.err;
      variables_.insert(exported(started.out));
    }
  }
  static void TearDownTestSuite() {
    for (const char* service : {"sshd", "slurm"})
      run_program(kServices + service + ".sh", {"stop", (services_ / service).string()}, "", {});
    std::error_code ignored;
    std::filesystem::remove_all(services_, ignored);
  }

  void SetUp() override {
    WorkflowTest::SetUp();
    mission_ = write_short_mission(scratch()).string();
    user_with_active_project("ada", "local");
  }
  Environment environment() const {
    Environment env = WorkflowTest::environment();
    for (const auto& [name, value] : variables_) env.set[name] = value;
    env.set["OMPI_ALLOW_RUN_AS_ROOT"] = "1";  // a job of several tasks runs mpirun, as root in CI
    env.set["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1";
    return env;
  }
  Outcome sd(const std::vector<std::string>& args) { return run_swarmdesign(args, "", environment()); }
  std::string sd_ok(const std::vector<std::string>& args) {
    const Outcome o = sd(args);
    EXPECT_EQ(o.exit_code, 0) << "swarmdesign " << args.front() << ": " << o.err;
    return o.out;
  }
  static std::string this_host() {
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
  }
  static std::string this_user() { return ::getpwuid(::geteuid())->pw_name; }

  /// A cluster project on `host`, running this build's swarmdesign, designing on the short AAC.
  void cluster_project(const std::string& name, const std::string& host, int budget) {
    sd_ok({"new-project", name, "--cluster", host, "--cluster-user", this_user(), "--cluster-dir",
           (scratch() / "cluster").string(), "--cluster-binary", ::sd::test::swarmdesign_binary()});
    sd_ok({"select-project", name});
    sd_ok({"set-mission", mission_});
    sd_ok({"set-budget", std::to_string(budget)});
  }
  json status() { return json::parse(sd_ok({"status", "--json"})); }
  /// Polls status until `done` holds for it; the last status.
  json follow(const std::function<bool(const json&)>& done, std::chrono::seconds timeout) {
    json s;
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      s = status();
      if (done(s)) return s;
      std::this_thread::sleep_for(500ms);
    }
    ADD_FAILURE() << "status never got there; last:\n" << s.dump(2);
    return s;
  }
  static bool in_state(const json& s, const std::string& state) { return s["design"]["state"] == state; }
  /// The same design made here, without Slurm: what the cluster must have found too.
  json local_design(int budget, int seed) {
    return design_outcome(sd_ok({"design", "--mission", mission_, "--budget", std::to_string(budget), "--seed",
                                 std::to_string(seed), "--fsm", "--chocolate", "--threads", "2", "--out",
                                 (scratch() / "here").string(), "--json"}));
  }

  std::string mission_;
  static inline std::filesystem::path services_;
  static inline std::map<std::string, std::string> variables_;
};

TEST_F(cluster_projects, OnTheLoginNodeADesignRunsAsASlurmJobOnTwoRanksAndComesHome) {
  cluster_project("login", this_host(), 1100);
  const json checked = json::parse(sd_ok({"cluster-check", "--json"}));
  EXPECT_TRUE(checked["ok"].get<bool>()) << checked.dump(2);
  EXPECT_EQ(checked["where"], "this machine");

  const std::string submitted = sd_ok({"run-design", "--fsm", "--chocolate", "--seed", "3", "--ntasks", "2", "--time", "5"});
  EXPECT_NE(submitted.find("Submitted to Slurm as job"), std::string::npos) << submitted;
  const json done = follow([](const json& s) { return in_state(s, "finished"); }, 180s);
  ASSERT_TRUE(in_state(done, "finished"));
  EXPECT_EQ(done["cluster_job"]["slurm_state"], "COMPLETED");
  EXPECT_EQ(done["cluster_job"]["settings"]["ntasks"], 2);

  // Bit for bit the design this machine makes alone, and it is home: test-design scores it here.
  const json here = local_design(1100, 3);
  EXPECT_EQ(done["design"]["best_configuration"], here["best"]["configuration"]);
  EXPECT_EQ(done["design"]["best_score"], here["best"]["mean_score"]);
  EXPECT_EQ(done["progress"]["experiments_used"], here["experiments_used"]);
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(done["design"]["folder"].get<std::string>()) / "design.db"));
  EXPECT_NE(sd_ok({"test-design", "--seeds", "1-2"}).find("Testing the best control software of design"), std::string::npos);
}

TEST_F(cluster_projects, StopDesignCancelsTheJobAndRunDesignResumesItWhereItStopped) {
  cluster_project("long", this_host(), 60000);
  sd_ok({"run-design", "--fsm", "--chocolate", "--seed", "4"});
  const json running = follow([](const json& s) { return s["cluster_job"]["slurm_state"] == "RUNNING" &&
                                                         s["progress"]["experiments_used"].get<int>() > 0; }, 120s);
  const std::string stopped = sd_ok({"stop-design"});
  EXPECT_NE(stopped.find("cancelled Slurm job"), std::string::npos) << stopped;
  const json after = status();
  EXPECT_EQ(after["design"]["state"], "interrupted");
  EXPECT_EQ(after["cluster_job"]["slurm_state"], "CANCELLED");
  EXPECT_NE(after["cluster_job"]["note"].get<std::string>().find("cancelled by stop-design"), std::string::npos);
  // The folder came home: status shows where the design stopped.
  const int used = after["progress"]["experiments_used"].get<int>();
  EXPECT_GE(used, running["progress"]["experiments_used"].get<int>());
  expect_error(sd({"stop-design"}), 1, "no design of long is running");

  const std::string again = sd_ok({"run-design"});
  EXPECT_NE(again.find("submitted again, it resumes from its last checkpoint"), std::string::npos) << again;
  const json resumed = follow([&](const json& s) { return s["cluster_job"]["slurm_state"] == "RUNNING" &&
                                                          s["progress"]["experiments_used"].get<int>() > used; }, 120s);
  EXPECT_EQ(resumed["design"]["id"], after["design"]["id"]);  // the same design, not a new one
  sd_ok({"stop-design"});
}

// The web app's Start in a cluster project submits a Slurm job (not a thread of the server),
// its status page follows the job, and its Stop cancels it: the same backend as the CLI's.
TEST_F(cluster_projects, FromTheWebAClusterProjectsStartGoesToSlurmAndStopCancelsIt) {
  cluster_project("webslurm", this_host(), 60000);
  // The server runs in this process and submits with this process' environment.
  for (const auto& [name, value] : variables_) ::setenv(name.c_str(), value.c_str(), 1);
  RunningServer server(home());
  WebClient browser(server.port());
  ASSERT_TRUE(browser.sign_in("ada", "ada-secret-pw")) << browser.last_refusal();

  const Answer started = browser.post("/api/projects/webslurm/designs",
                                      {{"architectures", "fsm"}, {"flavours", "chocolate"}, {"seed", "5"}});
  ASSERT_EQ(started.status, 200) << started.text;
  const auto page = [&browser] { return browser.get("/api/projects/webslurm/status").body; };
  json running;
  const auto end = std::chrono::steady_clock::now() + 120s;
  while (std::chrono::steady_clock::now() < end) {
    running = page();
    if (running["cluster_job"]["slurm_state"] == "RUNNING" && running["progress"]["experiments_used"].get<int>() > 0) break;
    std::this_thread::sleep_for(500ms);
  }
  ASSERT_EQ(running["cluster_job"]["slurm_state"], "RUNNING") << running.dump(2);
  EXPECT_FALSE(running["running_here"].get<bool>()) << "a cluster project's design runs in Slurm, not in the server";
  EXPECT_EQ(running["design"]["id"], started.body["id"]);
  // The CLI sees the same job.
  EXPECT_EQ(status()["cluster_job"]["job_id"], running["cluster_job"]["job_id"]);

  const Answer stopped = browser.post("/api/projects/webslurm/designs/stop", json::object());
  ASSERT_EQ(stopped.status, 200) << stopped.text;
  const json after = page();
  EXPECT_EQ(after["design"]["state"], "interrupted") << after.dump(2);
  EXPECT_EQ(after["cluster_job"]["slurm_state"], "CANCELLED");
}

// The web app's Start of an experiment in a cluster project goes where the CLI's goes (one
// backend, app::launch_experiment): a Slurm job array, not a thread of the server; its Stop
// cancels the array, and its Resume submits what is left to Slurm again.
TEST_F(cluster_projects, FromTheWebAClusterProjectsExperimentGoesToSlurmAndStopCancelsItsArray) {
  cluster_project("webarray", this_host(), 1100);
  for (const auto& [name, value] : variables_) ::setenv(name.c_str(), value.c_str(), 1);
  // The page reads mission files in the user's own projects only.
  const auto mission = write_short_mission(home() / "users" / "ada" / "projects" / "webarray", 2);
  const auto protocol = [&](int budget) {
    return json{{"name", "webtiny"}, {"designs", 2}, {"assessment_seeds", 2},
                {"missions", {{{"mission", mission.string()}, {"budget", budget},
                               {"conditions", {{{"name", "alone"}, {"architectures", {"fsm"}}, {"flavours", {"chocolate"}}}}}}}}};
  };
  RunningServer server(home());
  WebClient browser(server.port());
  ASSERT_TRUE(browser.sign_in("ada", "ada-secret-pw")) << browser.last_refusal();

  const Answer started = browser.post("/api/projects/webarray/experiments", {{"text", protocol(60000).dump()}});
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body["where"], "slurm");
  EXPECT_FALSE(started.body["experiment"]["running_here"].get<bool>()) << "a cluster project's experiment runs in Slurm";
  EXPECT_EQ(status()["experiments"][0]["state"], "running");

  const Answer stopped = browser.post("/api/projects/webarray/experiments/webtiny/stop", json::object());
  ASSERT_EQ(stopped.status, 200) << stopped.text;
  EXPECT_NE(stopped.body["stopping"].get<std::string>().find("cancelled Slurm array job"), std::string::npos) << stopped.text;
  EXPECT_EQ(status()["experiments"][0]["state"], "interrupted");
  EXPECT_EQ(browser.post("/api/projects/webarray/experiments/webtiny/stop", json::object()).status, 409);

  const Answer resumed = browser.post("/api/projects/webarray/experiments/webtiny/resume", json::object());
  ASSERT_EQ(resumed.status, 200) << resumed.text;
  EXPECT_EQ(resumed.body["where"], "slurm");
  EXPECT_EQ(status()["experiments"][0]["state"], "running");
  ASSERT_EQ(browser.post("/api/projects/webarray/experiments/webtiny/stop", json::object()).status, 200);
}

TEST_F(cluster_projects, OverSshADesignIsSubmittedFollowedAndBroughtBack) {
  cluster_project("remote", "127.0.0.1", 1100);
  const json checked = json::parse(sd_ok({"cluster-check", "--json"}));
  EXPECT_TRUE(checked["ok"].get<bool>()) << checked.dump(2);
  EXPECT_NE(checked["where"].get<std::string>().find("(ssh)"), std::string::npos);

  sd_ok({"run-design", "--fsm", "--chocolate", "--seed", "3"});
  const json done = follow([](const json& s) { return in_state(s, "finished"); }, 180s);
  ASSERT_TRUE(in_state(done, "finished"));
  EXPECT_EQ(done["design"]["best_configuration"], local_design(1100, 3)["best"]["configuration"]);
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(done["design"]["folder"].get<std::string>()) / "design.db"));
}

TEST_F(cluster_projects, FailuresAreOneLineTheProjectKeepsItsStateAndTheDesignGoesWhenSubmittedAgain) {
  // An unreachable host: nothing is submitted, status says why, cluster-check too.
  cluster_project("unreachable", "127.0.0.1", 1100);
  Environment env = environment();
  env.set["SWARMDESIGN_SSH"] += " -p 1";  // nothing listens on port 1
  const Outcome refused = run_swarmdesign({"run-design", "--fsm", "--chocolate"}, "", env);
  expect_error(refused, 1, "cannot reach " + this_user() + "@127.0.0.1 over ssh");
  const Outcome check = run_swarmdesign({"cluster-check"}, "", env);
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.out.find("MISSING connection"), std::string::npos) << check.out;
  const json s = status();
  EXPECT_EQ(s["design"]["state"], "interrupted");
  EXPECT_NE(s["cluster_job"]["note"].get<std::string>().find("cannot reach"), std::string::npos);
  // Reachable again, the same design goes.
  sd_ok({"run-design"});
  EXPECT_TRUE(in_state(follow([](const json& t) { return in_state(t, "finished"); }, 180s), "finished"));

  // sbatch refuses a partition that does not exist; with one that does, the design runs.
  cluster_project("partition", this_host(), 1100);
  expect_error(sd({"run-design", "--fsm", "--chocolate", "--partition", "nope"}), 1, "sbatch refused the job");
  EXPECT_EQ(status()["design"]["state"], "interrupted");
  const std::string before = snapshot();
  expect_error(sd({"run-design", "--time", "one hour"}), 2, "time");
  EXPECT_EQ(snapshot(), before);
  sd_ok({"run-design", "--partition", "debug"});
  const json done = follow([](const json& t) { return in_state(t, "finished"); }, 180s);
  EXPECT_EQ(done["cluster_job"]["settings"]["partition"], "debug");
}

TEST_F(cluster_projects, AJobCutByItsTimeLimitSaysSoAndResumesWhenSubmittedAgain) {
  // A design far longer than Slurm's smallest limit, one minute, and than the resumed job's
  // first seconds: 200 000 runs of the short AAC took about a minute on 2 cores, so the resumed
  // job sometimes finished before stop-design could stop it.
  cluster_project("limited", this_host(), 20000000);
  sd_ok({"run-design", "--fsm", "--chocolate", "--time", "1"});
  const json cut = follow([](const json& s) { return !in_state(s, "running"); }, 240s);
  EXPECT_EQ(cut["design"]["state"], "interrupted");
  EXPECT_EQ(cut["cluster_job"]["slurm_state"], "TIMEOUT");
  EXPECT_NE(cut["cluster_job"]["note"].get<std::string>().find("reached its time limit"), std::string::npos)
      << cut.dump(2);
  const int used = cut["progress"]["experiments_used"].get<int>();
  EXPECT_GT(used, 0);
  // The job submitted again may start while its predecessor still saves its last checkpoint
  // (Slurm's KillWait; a loaded machine made that one hold the design's lock for a while, and
  // the new job failed on it). It must wait for the lock, not fail: hold it here for 6 s.
  const std::string lock = cut["cluster_job"]["folder"].get<std::string>() + "/design/design.lock";
  ASSERT_TRUE(std::filesystem::exists(lock)) << lock;
  std::thread holder([&] { run_program("/usr/bin/flock", {lock, "sleep", "6"}, "", {}); });
  std::this_thread::sleep_for(1s);  // flock has taken it
  sd_ok({"run-design", "--time", "10"});
  holder.join();
  const json resumed = follow([&](const json& s) { return s["progress"]["experiments_used"].get<int>() > used; }, 120s);
  EXPECT_TRUE(in_state(resumed, "running")) << resumed.dump(2);
  const Outcome stopped = sd({"stop-design"});
  EXPECT_EQ(stopped.exit_code, 0) << stopped.err << "\nstatus before: " << resumed.dump(2) << "\nafter: " << status().dump(2);
}

TEST_F(cluster_projects, AnExperimentGoesAsOneJobArrayAndEndsAsTheLocalOneDoes) {
  const auto protocol = scratch() / "tiny.json";
  std::ofstream(protocol) << json{{"name", "tiny"}, {"designs", 3}, {"assessment_seeds", 3},
                                  {"missions", {{{"mission", mission_}, {"budget", 1100},
                                                 {"conditions", {{{"name", "alone"}, {"architectures", {"fsm"}},
                                                                  {"flavours", {"chocolate"}}}}}}}}};
  // The same protocol made here, in the local project.
  sd_ok({"experiment", "--file", protocol.string(), "--threads", "2", "--json"});
  const json here = json::parse(sd_ok({"report", "tiny", "--out", (scratch() / "here").string(), "--json"}));

  cluster_project("array", this_host(), 1100);
  const std::string submitted = sd_ok({"experiment", "--file", protocol.string(), "--time", "5"});
  EXPECT_NE(submitted.find("3 of 3 designs submitted to Slurm as array job"), std::string::npos) << submitted;
  // Every task leaves its result in the array's folder (this machine is the cluster) ...
  const auto folder_at = submitted.find("(folder ");
  ASSERT_NE(folder_at, std::string::npos) << submitted;
  const std::filesystem::path folder = submitted.substr(folder_at + 8, submitted.find(')', folder_at) - folder_at - 8);
  const auto results = [&] {
    int n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      n += std::filesystem::exists(entry.path() / "result.json") ? 1 : 0;
    return n;
  };
  for (const auto end = std::chrono::steady_clock::now() + 240s; results() < 3 && std::chrono::steady_clock::now() < end;)
    std::this_thread::sleep_for(500ms);
  ASSERT_EQ(results(), 3) << "the array's tasks never all wrote their results in " << folder;
  // ... yet status only reads: polled, it brings nothing home and assesses nothing.
  for (int poll = 0; poll < 3; ++poll) {
    const json polled = status();
    EXPECT_EQ(polled["experiments"][0]["state"], "running") << polled.dump(2);
    EXPECT_EQ(polled["experiments"][0]["designs_done"], 0) << polled.dump(2);
  }
  EXPECT_NE(sd_ok({"status"}).find("swarmdesign collect"), std::string::npos);
  // collect does, as the tasks end for Slurm.
  json done;
  int home = 0;
  for (const auto end = std::chrono::steady_clock::now() + 120s; std::chrono::steady_clock::now() < end;) {
    const json collected = json::parse(sd_ok({"collect", "--json"}));
    home += collected["designs_home"].get<int>();
    done = collected["progress"];
    if (done[0]["state"] == "finished") break;
    std::this_thread::sleep_for(500ms);
  }
  EXPECT_EQ(done[0]["state"], "finished") << done.dump(2);
  EXPECT_EQ(done[0]["designs_done"], 3);
  EXPECT_EQ(home, 3);
  const json there = json::parse(sd_ok({"report", "tiny", "--out", (scratch() / "there").string(), "--json"}));
  ASSERT_EQ(there["designs"].size(), here["designs"].size());
  for (std::size_t i = 0; i < here["designs"].size(); ++i) {
    EXPECT_EQ(there["designs"][i]["configuration"], here["designs"][i]["configuration"]) << i;
    EXPECT_EQ(there["designs"][i]["scores"], here["designs"][i]["scores"]) << i;
  }
  // Asked again, a finished experiment is not submitted again.
  EXPECT_NE(sd_ok({"experiment", "--file", protocol.string()}).find("has finished"), std::string::npos);
}

TEST_F(cluster_projects, ALocalProjectRefusesSlurmOptionsAndStopDesignStopsItsProcess) {
  expect_error(sd({"run-design", "--ntasks", "4"}), 2, "for a cluster project");
  sd_ok({"set-mission", mission_});
  sd_ok({"set-budget", "60000"});
  sd_ok({"run-design", "--detach", "--fsm", "--chocolate"});
  follow([](const json& s) { return s["progress"]["experiments_used"].get<int>() > 0; }, 60s);
  EXPECT_NE(sd_ok({"stop-design"}).find("stopped process"), std::string::npos);
  EXPECT_EQ(status()["design"]["state"], "interrupted");
}

}  // namespace
}  // namespace sd::test
