// The web app's stream, measured against the real `swarmdesign run-exp` in a child process on
// loopback, as a browser meets it:
//   BM_RunStartToFirstFrame  run started (POST answered) -> first `frames` event (AAC)
//   BM_ExecWholeRun       POST -> `end`: frames delivered per second at full speed
//   BM_ServerCpuPerViewer the server's CPU time (from /proc) for one run watched by N viewers
// Run: ./build/bench/web_bench   (Exec -> first frame and frame rate in the browser: bench/web_viewer.mjs)
#include <benchmark/benchmark.h>
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

const char* kFsm =
    "--fsm-config --nstates 2 --s0 0 --rwm0 50 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.5 --s1 1 --n1 1 --n1x0 0 --c1x0 1 "
    "--p1x0 0.5";

/// The real server with one signed-up user, for the whole benchmark run.
class Server {
 public:
  Server() {
    home_ = std::filesystem::temp_directory_path() / ("sd-web-bench-" + std::to_string(::getpid()));
    std::filesystem::remove_all(home_);
    std::filesystem::create_directories(home_ / "web-root");  // the API alone is measured
    const std::string env = "SWARMDESIGN_HOME='" + home_.string() + "' ";
    if (std::system(("printf 'bench-password\\n' | " + env + SWARMDESIGN_BINARY " sign-up bench --password-stdin >/dev/null").c_str()) != 0)
      throw std::runtime_error("sign-up failed");
    port_ = 18000 + ::getpid() % 1000;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setenv("SWARMDESIGN_HOME", home_.c_str(), 1);
      const std::string port = std::to_string(port_);
      ::execl(SWARMDESIGN_BINARY, SWARMDESIGN_BINARY, "run-exp", "--port", port.c_str(), "--web-root",
              (home_ / "web-root").c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_tcp_nodelay(true);
    for (int i = 0; i < 100 && !client_->Get("/"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const auto r = client_->Post("/api/sign-in", R"({"name":"bench","password":"bench-password"})", "application/json");
    if (!r || r->status != 200) throw std::runtime_error("sign-in failed");
    const std::string cookie = r->get_header_value("Set-Cookie");
    headers_ = {{"Cookie", cookie.substr(0, cookie.find(';'))},
                {"X-CSRF-Token", nlohmann::json::parse(r->body).at("csrf").get<std::string>()}};
  }
  ~Server() {
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
    std::filesystem::remove_all(home_);
  }

  std::int64_t start_run(int seed) {
    const auto r = client_->Post("/api/runs", headers_,
                                 nlohmann::json{{"text", kFsm}, {"mission", "aac"}, {"seed", seed}}.dump(), "application/json");
    if (!r || r->status != 200) throw std::runtime_error("exec failed");
    return nlohmann::json::parse(r->body).at("id").get<std::int64_t>();
  }

  /// Reads the run's stream until `stop_at` appears; returns the bytes read.
  std::size_t read(std::int64_t run, const std::string& stop_at) const {
    httplib::Client c("127.0.0.1", port_);
    c.set_tcp_nodelay(true);  // as browsers do
    std::string seen;
    c.Get(("/api/runs/" + std::to_string(run) + "/stream").c_str(), headers_, [&](const char* data, std::size_t n) {
      seen.append(data, n);
      return seen.find(stop_at) == std::string::npos;
    });
    return seen.size();
  }

  /// The server process' user + system CPU time, in seconds.
  double cpu_seconds() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    std::istringstream fields(text.substr(text.rfind(')') + 2));
    std::string f;
    long utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> f; ++i) {
      if (i == 14) utime = std::stol(f);
      if (i == 15) stime = std::stol(f);
    }
    return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }

 private:
  std::filesystem::path home_;
  int port_ = 0;
  pid_t pid_ = 0;
  std::unique_ptr<httplib::Client> client_;
  httplib::Headers headers_;
};

Server& server() {
  static Server s;
  return s;
}

void BM_RunStartToFirstFrame(benchmark::State& state) {
  int seed = 1;
  double post_ms = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    const std::int64_t run = server().start_run(seed++);
    const auto posted = Clock::now();
    server().read(run, "event: frames");
    // From the POST's answer: cpp-httplib's client spends ~35 ms on a POST that curl and the
    // browser send in ~5 ms (post_ms shows it), so the whole Exec -> first frame is measured in
    // the browser (bench/web_viewer.mjs).
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - posted).count());
    post_ms += std::chrono::duration<double, std::milli>(posted - start).count();
    // Untimed: the run ends before the next starts, so runs do not pile up against the
    // server's limit of 4 simulating per user (nor compete for the cores being measured).
    server().read(run, "event: end");
  }
  state.counters["post_ms"] = post_ms / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RunStartToFirstFrame)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

void BM_ExecWholeRun(benchmark::State& state) {
  int seed = 100;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::int64_t run = server().start_run(seed++);
    bytes = server().read(run, "event: end");
  }
  // 1201 frames (placement and 1200 ticks) per run.
  state.counters["frames_per_s"] = benchmark::Counter(1201.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["stream_kB"] = static_cast<double>(bytes) / 1000.0;
}
BENCHMARK(BM_ExecWholeRun)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();

void BM_ServerCpuPerViewer(benchmark::State& state) {
  const auto viewers = static_cast<std::size_t>(state.range(0));
  int seed = 1000;
  double cpu = 0.0;
  for (auto _ : state) {
    const double before = server().cpu_seconds();
    const std::int64_t run = server().start_run(seed++);
    std::vector<std::thread> threads;
    for (std::size_t v = 0; v < viewers; ++v) threads.emplace_back([run] { server().read(run, "event: end"); });
    for (auto& t : threads) t.join();
    cpu += server().cpu_seconds() - before;
  }
  state.counters["server_cpu_ms_per_run"] = 1000.0 * cpu / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ServerCpuPerViewer)->Arg(1)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
