// HTTP under load (issue #34): the real `swarmdesign run-exp` in a child process on loopback,
// with a temporary home, held by N concurrent clients (200 by default) for a fixed time. Each
// client is a browser tab doing one thing in a loop, with the pauses the front end has:
//   sign-in  its own account: sign in, read the session, sign out (Argon2id each time)
//   parse    the editor's parse route, one string in four with a bad token (400 + token expected)
//   exec     Exec: start an AAC run, read its event stream to `end`; a 409 (the per-user or
//            per-server limit of simulating runs) is what the page shows as "refused": the tab
//            waits a second and presses Exec again, as a user would
//   monitor  the design monitor: polls a running design's status every second (monitor.js), and
//            its designs list every fifth poll; the designs are small ones started at set-up
// It counts per request kind the answers, the expected refusals, the errors (a connection
// failure, a timeout, a status or body that is not the expected one, an Exec score that differs
// from an earlier run of the same seed) and the latency's p50, p95, p99 and max; it samples the
// server's RSS (/proc) every second and says whether it stays flat after the warm-up.
// Run: ./build/bench/load_bench [--clients 200] [--seconds 60] [--json]   (see --help)
//
// --lab is another scenario (issue #56's "20 accounts with 2 designs each on a 2-core server,
// sign-in and status polls answer within 1 s at the 95th percentile, quotas holding"): N
// accounts (20), the first the administrator, who sets the server's default quota of runs per
// day (`admin quota --default`) to exactly the designs each account starts (2 x the budget).
// Each account makes its projects and starts a design in each, is refused a third by the runs
// quota (409 "runs quota: ...") and reads its use from /api/quota; the designs are then
// stopped and resumed (a resume costs no quota), as many as the server takes at once (its own
// limit of designs refuses the rest). Then, for the measured time, each account has one tab
// polling its designs' status every second and one signing in, reading the session and
// signing out every 2-5 s; at the end the third design is refused again and the quota read
// again. Verdict: sign-in's and the status polls' p95 <= 1000 ms.
// Run: ./build/bench/load_bench --lab [--accounts 20] [--designs-per-account 2] [--seconds 60]
#include <CLI/CLI.hpp>
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

const char* kFsm =
    "--fsm-config --nstates 2 --s0 0 --rwm0 50 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.5 --s1 1 --n1 1 --n1x0 0 --c1x0 1 "
    "--p1x0 0.5";
const char* kBt =
    "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 44 --att01 5 "
    "--p01 0 --n1 0 --nchild1 2 --n10 6 --c10 41 --p10 0.1 --n11 5 --a11 41 --p11 0";
const char* kBadToken = "--fsm-config --nstates 1 --s0 0 --rwmX 5";
const char* kPassword = "load-bench-password";

struct Options {
  int clients = 200;
  double seconds = 60;
  double warmup = 15;  // RSS before this is not judged: the run registry fills its 64 kept runs
  std::vector<int> mix{10, 40, 20, 30};  // % sign-in, parse, exec, monitor
  int designs = 2;
  double signin_pause = 2, parse_pause = 0.5, exec_pause = 2, poll = 1;
  bool keep_alive = true;  // as browsers
  bool json = false;
  std::string binary = SWARMDESIGN_BINARY;
  // --lab
  bool lab = false;
  int accounts = 20;
  int designs_per_account = 2;
  long long budget = 200000;
  std::vector<double> lab_signin_pause{2, 5};  // seconds, drawn uniformly between the two
  double p95_target_ms = 1000;
  int running_designs = -1;  // designs resumed for the measured time; -1: as many as the server takes
};

enum Kind {
  kSignIn, kSession, kSignOut, kParse, kExecStart, kExecFirstFrame, kExecEnd, kStatus, kDesigns,
  // --lab's set-up and checks
  kProject, kDesignStart, kOverQuota, kQuota, kDesignStop, kDesignResume,
  kKinds
};
const char* const kKindNames[kKinds] = {"sign-in",         "session",        "sign-out",       "parse",
                                        "exec-start",      "exec-first-frame", "exec-whole-run", "monitor-status",
                                        "monitor-designs", "project-create", "design-start",   "design-over-quota",
                                        "quota-read",      "design-stop",    "design-resume"};
/// The kinds of the first scenario, in its table's order.
const std::vector<Kind> kLoadKinds{kSignIn, kSession, kSignOut, kParse, kExecStart, kExecFirstFrame, kExecEnd, kStatus, kDesigns};

/// What every client reports, per request kind.
class Recorder {
 public:
  void ok(Kind kind, double ms) {
    std::lock_guard lock(mutex_);
    ms_[kind].push_back(ms);
  }
  void refused(Kind kind, double ms) {
    std::lock_guard lock(mutex_);
    ms_[kind].push_back(ms);
    ++refused_[kind];
  }
  void error(Kind kind, const std::string& what) {
    std::lock_guard lock(mutex_);
    ++errors_[kind];
    if (++samples_[kKindNames[kind] + (": " + what)] == 1) std::cerr << "error: " << kKindNames[kind] << ": " << what << "\n";
  }
  long total_errors() const {
    std::lock_guard lock(mutex_);
    long n = 0;
    for (long e : errors_) n += e;
    return n;
  }
  /// The figures of `kinds`.
  json document(const std::vector<Kind>& kinds) const;

 private:
  mutable std::mutex mutex_;
  std::vector<double> ms_[kKinds];
  long refused_[kKinds] = {};
  long errors_[kKinds] = {};
  std::map<std::string, long> samples_;  // error message -> count
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];  // nearest rank
}

json Recorder::document(const std::vector<Kind>& shown) const {
  std::lock_guard lock(mutex_);
  json kinds = json::object();
  for (const Kind k : shown) {
    const std::vector<double>& v = ms_[k];
    kinds[kKindNames[k]] = {{"answers", v.size()},
                            {"refused", refused_[k]},
                            {"errors", errors_[k]},
                            {"p50_ms", percentile(v, 50)},
                            {"p95_ms", percentile(v, 95)},
                            {"p99_ms", percentile(v, 99)},
                            {"max_ms", v.empty() ? 0.0 : *std::max_element(v.begin(), v.end())}};
  }
  json errors = json::object();
  for (const auto& [what, n] : samples_) errors[what] = n;
  return {{"kinds", kinds}, {"error_messages", errors}};
}

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// One signed-in browser: the session cookie and its CSRF token (tabs of one account share it).
struct Session {
  std::string user, cookie, csrf;
  httplib::Headers headers() const { return {{"Cookie", cookie}, {"X-CSRF-Token", csrf}}; }
};

std::string describe(const httplib::Result& r) {
  if (!r) return "no answer (" + httplib::to_string(r.error()) + ")";
  std::string body = r->body.substr(0, 120);
  std::replace(body.begin(), body.end(), '\n', ' ');
  return "HTTP " + std::to_string(r->status) + " " + body;
}

/// The server under test and its temporary home.
class Server {
 public:
  explicit Server(const std::string& binary) : binary_(binary) {
    home_ = std::filesystem::temp_directory_path() / ("sd-load-bench-" + std::to_string(::getpid()));
    std::filesystem::remove_all(home_);
    std::filesystem::create_directories(home_ / "web-root");  // the API alone is measured
  }
  ~Server() {
    stop();
    std::filesystem::remove_all(home_);
  }

  void sign_up(const std::string& name) const {
    const std::string command = std::string("printf '%s\\n' '") + kPassword + "' | SWARMDESIGN_HOME='" + home_.string() +
                                "' '" + binary_ + "' sign-up " + name + " --password-stdin >/dev/null";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("sign-up " + name + " failed");
  }

  /// `swarmdesign ARGS` as `user` (signed in first, as a person at the terminal would), with the
  /// server's home; its standard output. Throws when either command fails.
  std::string cli(const std::string& user, const std::string& args) const {
    const std::string env = "SWARMDESIGN_HOME='" + home_.string() + "' '" + binary_ + "' ";
    const std::string command = std::string("printf '%s\\n' '") + kPassword + "' | " + env + "sign-in " + user +
                                " --password-stdin >/dev/null && " + env + args;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + args);
    std::string out;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    if (::pclose(pipe) != 0) throw std::runtime_error("`swarmdesign " + args + "` as " + user + " failed");
    return out;
  }

  /// The server's CPU time so far (user + system), in seconds; 0 once it has gone.
  double cpu_seconds() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t paren = stat.rfind(')');
    if (paren == std::string::npos) return 0;
    std::istringstream fields(stat.substr(paren + 2));
    std::string field;
    double ticks = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i)  // fields 14 and 15: utime, stime
      if (i >= 14) ticks += std::stod(field);
    return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }

  void start() {
    for (int attempt = 0; attempt < 20 && pid_ == 0; ++attempt) {
      port_ = 20000 + static_cast<int>((static_cast<unsigned>(::getpid()) * 7 + static_cast<unsigned>(attempt) * 131) % 20000);
      pid_ = ::fork();
      if (pid_ == 0) {
        ::setenv("SWARMDESIGN_HOME", home_.c_str(), 1);
        const std::string port = std::to_string(port_);
        if (!std::freopen((home_ / "server.log").c_str(), "a", stdout)) ::_exit(126);
        ::execl(binary_.c_str(), binary_.c_str(), "run-exp", "--port", port.c_str(), "--web-root",
                (home_ / "web-root").c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
      }
      httplib::Client probe("127.0.0.1", port_);
      for (int i = 0; i < 200; ++i) {
        if (probe.Get("/")) return;
        if (::waitpid(pid_, nullptr, WNOHANG) == pid_) break;  // the port was taken: try another
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      pid_ = 0;
    }
    throw std::runtime_error("the server did not start");
  }

  /// SIGTERM, as Ctrl-C; "exit 0" when it stopped cleanly.
  std::string stop() {
    if (pid_ == 0) return exit_;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    exit_ = WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                              : "signal " + std::to_string(WTERMSIG(status));
    return exit_;
  }

  /// The server's resident set (KiB) and thread count, from /proc; 0 once it has gone.
  std::pair<long, long> rss_kib_and_threads() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
    std::string line;
    long rss = 0, threads = 0;
    while (std::getline(in, line)) {
      if (line.rfind("VmRSS:", 0) == 0) rss = std::stol(line.substr(6));
      if (line.rfind("Threads:", 0) == 0) threads = std::stol(line.substr(8));
    }
    return {rss, threads};
  }

  int port() const { return port_; }

 private:
  std::string binary_;
  std::filesystem::path home_;
  int port_ = 0;
  pid_t pid_ = 0;
  std::string exit_;
};

/// A connection of a tab; `keep_alive` as a browser, which keeps it between requests.
std::unique_ptr<httplib::Client> connect(int port, bool keep_alive) {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", port);
  c->set_tcp_nodelay(true);
  c->set_keep_alive(keep_alive);
  c->set_connection_timeout(10, 0);
  c->set_read_timeout(30, 0);  // a stream sends a comment every second while it waits
  c->set_write_timeout(10, 0);
  return c;
}

Session sign_in(httplib::Client& c, const std::string& name) {
  const auto r = c.Post("/api/sign-in", json{{"name", name}, {"password", kPassword}}.dump(), "application/json");
  if (!r || r->status != 200) throw std::runtime_error("sign-in " + name + ": " + describe(r));
  const std::string cookie = r->get_header_value("Set-Cookie");
  return {name, cookie.substr(0, cookie.find(';')), json::parse(r->body).at("csrf").get<std::string>()};
}

/// Everything the clients share.
struct Load {
  const Options& options;
  int port;
  Recorder recorder;
  Clock::time_point end;
  std::mutex scores_mutex;
  std::map<int, std::string> scores;  // seed -> the `end` event's score, which every run of it must repeat
  std::atomic<long> runs_ended{0};

  bool running() const { return Clock::now() < end; }
  /// Sleeps about `seconds` (±25 %, so that the tabs do not march in step), never past the end.
  void pause(double seconds, std::mt19937& random) const { pause_between(0.75 * seconds, 1.25 * seconds, random); }
  /// Sleeps between `least` and `most` seconds (uniformly), never past the end.
  void pause_between(double least, double most, std::mt19937& random) const {
    std::uniform_real_distribution<double> seconds(least, most);
    const auto until = std::min(end, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                         std::chrono::duration<double>(seconds(random))));
    std::this_thread::sleep_until(until);
  }
};

/// What the bench says as it goes, on stderr: --json's stdout stays JSON.
void progress(const std::string& what) { std::cerr << "load_bench: " << what << std::endl; }

/// The server's RSS and threads once a second from `start` until the load ends, and every 10 s a
/// progress line (with `more`: what the scenario counts besides errors).
struct ServerSamples {
  std::vector<double> rss_mib;
  std::vector<long> threads;
};
ServerSamples sample_server(const Server& server, const Load& load, Clock::time_point start,
                            const std::function<std::string()>& more) {
  ServerSamples out;
  for (int s = 0; Clock::now() < load.end; ++s) {
    const auto [rss, count] = server.rss_kib_and_threads();
    out.rss_mib.push_back(static_cast<double>(rss) / 1024.0);
    out.threads.push_back(count);
    if (s % 10 == 0)
      progress("t=" + std::to_string(s) + " s: RSS " + std::to_string(static_cast<int>(out.rss_mib.back())) + " MiB, " +
               std::to_string(count) + " threads, " + more() + std::to_string(load.recorder.total_errors()) + " errors");
    std::this_thread::sleep_until(start + std::chrono::seconds(s + 1));
  }
  return out;
}

/// The errors of every kind of request in the document, also written into it as "errors".
long count_errors(json& doc) {
  long errors = 0;
  for (const auto& [name, k] : doc["kinds"].items()) errors += k["errors"].get<long>();
  doc["errors"] = errors;
  return errors;
}

/// Signs `name` in, reads the session and signs out, again and again, `least` to `most` seconds apart.
void sign_in_tab(Load& load, const std::string& name, double least, double most, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  while (load.running()) {
    auto start = Clock::now();
    const auto in = c->Post("/api/sign-in", json{{"name", name}, {"password", kPassword}}.dump(), "application/json");
    if (!in || in->status != 200 || in->get_header_value("Set-Cookie").empty()) {
      load.recorder.error(kSignIn, describe(in));
      load.pause_between(least, most, random);
      continue;
    }
    load.recorder.ok(kSignIn, ms_since(start));
    const std::string cookie = in->get_header_value("Set-Cookie");
    const Session s{name, cookie.substr(0, cookie.find(';')), json::parse(in->body).value("csrf", "")};

    start = Clock::now();
    const auto session = c->Get("/api/session", s.headers());
    if (session && session->status == 200 && json::parse(session->body, nullptr, false).value("user", "") == name)
      load.recorder.ok(kSession, ms_since(start));
    else
      load.recorder.error(kSession, describe(session));

    start = Clock::now();
    const auto out = c->Post("/api/sign-out", s.headers(), "{}", "application/json");
    if (out && out->status == 200) load.recorder.ok(kSignOut, ms_since(start));
    else load.recorder.error(kSignOut, describe(out));
    load.pause_between(least, most, random);
  }
}

void parse_tab(Load& load, const Session& s, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  for (auto i = random() % 4; load.running(); ++i) {
    const bool bad = i % 4 == 3;
    const char* text = bad ? kBadToken : (i % 2 == 0 ? kFsm : kBt);
    const auto start = Clock::now();
    const auto r = c->Post("/api/parse", s.headers(), json{{"text", text}}.dump(), "application/json");
    const double ms = ms_since(start);
    bool expected = false;
    if (r && r->status == (bad ? 400 : 200)) {
      const json body = json::parse(r->body, nullptr, false);
      expected = bad ? body.value("token", "") == "--rwmX" : body.contains("software") && body.contains("text");
    }
    if (expected) load.recorder.ok(kParse, ms);
    else load.recorder.error(kParse, describe(r));
    load.pause(load.options.parse_pause, random);
  }
}

/// Reads a run's stream to its `end`; checks the score against other runs of the same seed.
void read_stream(Load& load, const Session& s, std::int64_t id, int seed, Clock::time_point posted) {
  auto c = connect(load.port, load.options.keep_alive);  // EventSource has its own connection
  std::string seen;
  bool first = false;
  std::size_t scanned = 0;
  std::size_t final_at = std::string::npos;  // where `end` (or `failure`) begins, once seen
  const auto r = c->Get(("/api/runs/" + std::to_string(id) + "/stream").c_str(), s.headers(),
                        [&](const char* data, std::size_t n) {
                          seen.append(data, n);
                          if (!first && seen.find("event: frames", scanned) != std::string::npos) {
                            first = true;
                            load.recorder.ok(kExecFirstFrame, ms_since(posted));
                          }
                          if (final_at == std::string::npos)
                            final_at = std::min(seen.find("event: end", scanned), seen.find("event: failure", scanned));
                          scanned = seen.size() < 16 ? 0 : seen.size() - 16;
                          // Stop once the last event is whole (its blank line): a chunk may end
                          // between "event: end" and its data, which then was counted an error.
                          return final_at == std::string::npos || seen.find("\n\n", final_at) == std::string::npos;
                        });
  const std::size_t at = seen.find("event: end\ndata: ");
  if (at == std::string::npos) {
    // The receiver stops the read at `end`, which cpp-httplib reports as Canceled: only its
    // absence is an error.
    load.recorder.error(kExecEnd, r ? describe(r) + " without an end event" : describe(r));
    if (!first) load.recorder.error(kExecFirstFrame, "no frames");
    return;
  }
  const std::size_t eol = seen.find('\n', at + 17);
  const json end = json::parse(seen.substr(at + 17, eol - at - 17), nullptr, false);
  if (!end.is_object() || !end.contains("score")) {
    load.recorder.error(kExecEnd, "a malformed end event");
    return;
  }
  const std::string score = end["score"].dump();
  {
    std::lock_guard lock(load.scores_mutex);
    const auto [it, added] = load.scores.emplace(seed, score);
    if (!added && it->second != score) {
      load.recorder.error(kExecEnd, "seed " + std::to_string(seed) + " scored " + score + ", earlier " + it->second);
      return;
    }
  }
  ++load.runs_ended;
  load.recorder.ok(kExecEnd, ms_since(posted));
}

void exec_tab(Load& load, const Session& s, int first_seed, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  for (int seed = first_seed; load.running();) {
    const auto start = Clock::now();
    const auto r = c->Post("/api/runs", s.headers(), json{{"text", kFsm}, {"mission", "aac"}, {"seed", seed}}.dump(),
                           "application/json");
    const double ms = ms_since(start);
    if (r && r->status == 409) {  // the page says "refused: ...": press Exec again a second later
      load.recorder.refused(kExecStart, ms);
      load.pause(1.0, random);
      continue;
    }
    const json body = r && r->status == 200 ? json::parse(r->body, nullptr, false) : json();
    if (!body.is_object() || !body.contains("id")) {
      load.recorder.error(kExecStart, describe(r));
      load.pause(load.options.exec_pause, random);
      continue;
    }
    load.recorder.ok(kExecStart, ms);
    read_stream(load, s, body["id"].get<std::int64_t>(), seed, start);
    seed = seed % 8 + 1;  // 8 seeds over and over: every score is compared with earlier runs'
    load.pause(load.options.exec_pause, random);
  }
}

void monitor_tab(Load& load, const Session& s, const std::string& project, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  for (auto poll = random() % 5; load.running(); ++poll) {
    auto start = Clock::now();
    const auto r = c->Get(("/api/projects/" + project + "/status?race_log=false").c_str(), s.headers());
    const json status = r && r->status == 200 ? json::parse(r->body, nullptr, false) : json();
    if (status.is_object() && status.contains("design") && status.contains("running_here"))
      load.recorder.ok(kStatus, ms_since(start));
    else
      load.recorder.error(kStatus, describe(r));
    if (poll % 5 == 0) {
      start = Clock::now();
      const auto d = c->Get(("/api/projects/" + project + "/designs").c_str(), s.headers());
      const json list = d && d->status == 200 ? json::parse(d->body, nullptr, false) : json();
      if (list.is_array() && !list.empty()) load.recorder.ok(kDesigns, ms_since(start));
      else load.recorder.error(kDesigns, describe(d));
    }
    load.pause(load.options.poll, random);
  }
}

/// The table of `kinds` (and the error messages) of a document of Recorder::document.
void print_kinds(const json& doc, const std::vector<Kind>& kinds) {
  std::printf("%-17s %8s %8s %7s %9s %9s %9s %9s\n", "kind", "answers", "refused", "errors", "p50 ms", "p95 ms",
              "p99 ms", "max ms");
  for (const Kind k : kinds) {
    const json& r = doc["kinds"][kKindNames[k]];
    std::printf("%-17s %8ld %8ld %7ld %9.1f %9.1f %9.1f %9.1f\n", kKindNames[k], r["answers"].get<long>(),
                r["refused"].get<long>(), r["errors"].get<long>(), r["p50_ms"].get<double>(), r["p95_ms"].get<double>(),
                r["p99_ms"].get<double>(), r["max_ms"].get<double>());
  }
  for (const auto& [what, n] : doc["error_messages"].items()) std::printf("  %ld x %s\n", n.get<long>(), what.c_str());
}

/// The floors (lowest samples) of the first and last quarter after the warm-up; flat when the
/// last is within 5 % (or 8 MiB) of the first. Floors, because any sample may catch up to four
/// sign-ins' Argon2id buffers (64 MiB each, freed at once), which swing even a quarter's median
/// by +-50 MiB; a leak raises the floor, those buffers only what lies above it.
json rss_verdict(const std::vector<double>& mib, std::size_t warmup) {
  if (mib.size() < warmup + 8) return {{"flat", nullptr}, {"note", "too few samples after the warm-up"}};
  const std::vector<double> judged(mib.begin() + static_cast<long>(warmup), mib.end());
  const std::size_t q = judged.size() / 4;
  auto floor_of = [](std::vector<double> v) { return *std::min_element(v.begin(), v.end()); };
  const double first = floor_of({judged.begin(), judged.begin() + static_cast<long>(q)});
  const double last = floor_of({judged.end() - static_cast<long>(q), judged.end()});
  const double growth = last - first;
  return {{"first_quarter_mib", first}, {"last_quarter_mib", last}, {"growth_mib", growth},
          {"growth_percent", 100.0 * growth / first}, {"flat", growth <= std::max(0.05 * first, 8.0)}};
}

int run(const Options& o) {
  if (o.mix.size() != 4) throw std::runtime_error("--mix takes four percentages: sign-in,parse,exec,monitor");
  const int sum = o.mix[0] + o.mix[1] + o.mix[2] + o.mix[3];
  int counts[4];
  int given = 0;
  for (int k = 1; k < 4; ++k) given += counts[k] = o.clients * o.mix[static_cast<std::size_t>(k)] / sum;
  counts[0] = o.clients - given;
  const int signin = counts[0], parse = counts[1], exec = counts[2], monitor = counts[3];
  const int designs = monitor > 0 ? std::max(1, o.designs) : 0;

  Server server(o.binary);
  // Accounts: one per sign-in tab (its own name); the exec tabs four to an account (the
  // per-user limit of simulating runs), the parse tabs share those; one per design.
  const int editors = std::max(1, (exec + 3) / 4);
  progress("signing up " + std::to_string(signin + editors + designs) + " accounts");
  for (int i = 0; i < signin; ++i) server.sign_up("signin" + std::to_string(i));
  for (int i = 0; i < editors; ++i) server.sign_up("editor" + std::to_string(i));
  for (int i = 0; i < designs; ++i) server.sign_up("owner" + std::to_string(i));
  server.start();
  progress("server on port " + std::to_string(server.port()));

  auto setup = connect(server.port(), false);
  std::vector<Session> editor_sessions, owner_sessions;
  for (int i = 0; i < editors; ++i) editor_sessions.push_back(sign_in(*setup, "editor" + std::to_string(i)));
  for (int i = 0; i < designs; ++i) owner_sessions.push_back(sign_in(*setup, "owner" + std::to_string(i)));
  if (designs > 0) {
    const auto space = setup->Get("/api/design-space?architectures=fsm&flavours=chocolate", owner_sessions[0].headers());
    if (!space || space->status != 200) throw std::runtime_error("design-space: " + describe(space));
    const int budget = json::parse(space->body).at("minimum_budget").get<int>();
    for (int i = 0; i < designs; ++i) {
      const Session& s = owner_sessions[static_cast<std::size_t>(i)];
      const auto p = setup->Post("/api/projects", s.headers(),
                                 json{{"name", "load"}, {"mission", "aac"}, {"budget", budget}}.dump(), "application/json");
      if (!p || p->status != 200) throw std::runtime_error("new project: " + describe(p));
      const auto d = setup->Post("/api/projects/load/designs", s.headers(),
                                 json{{"architectures", "fsm"}, {"flavours", "chocolate"}, {"seed", i + 1}}.dump(),
                                 "application/json");
      if (!d || d->status != 200) throw std::runtime_error("start a design: " + describe(d));
    }
    progress("started " + std::to_string(designs) + " designs of " + std::to_string(budget) + " runs (AAC, FSM, Chocolate)");
  }

  Load load{o, server.port(), {}, {}, {}, {}, {}};
  const auto start = Clock::now();
  load.end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  progress(std::to_string(o.clients) + " clients (" + std::to_string(signin) + " sign-in, " + std::to_string(parse) +
           " parse, " + std::to_string(exec) + " exec, " + std::to_string(monitor) + " monitor) for " +
           std::to_string(static_cast<int>(o.seconds)) + " s");
  std::vector<std::thread> tabs;
  for (int i = 0; i < o.clients; ++i) {
    tabs.emplace_back([&, i] {
      std::mt19937 random(static_cast<unsigned>(i) * 7919u + 1u);
      // The tabs open over the first second, not in one burst.
      std::this_thread::sleep_for(std::chrono::milliseconds(random() % 1000));
      const auto idx = static_cast<std::size_t>(i);
      const Kind kind = i < signin ? kSignIn : i < signin + parse ? kParse : i < signin + parse + exec ? kExecStart : kStatus;
      try {
        if (i < signin) sign_in_tab(load, "signin" + std::to_string(i), 0.75 * o.signin_pause, 1.25 * o.signin_pause, random);
        else if (i < signin + parse) parse_tab(load, editor_sessions[idx % editor_sessions.size()], random);
        else if (i < signin + parse + exec) {
          const auto e = static_cast<std::size_t>(i - signin - parse);
          exec_tab(load, editor_sessions[e / 4], static_cast<int>(e % 8) + 1, random);
        } else {
          monitor_tab(load, owner_sessions[idx % owner_sessions.size()], "load", random);
        }
      } catch (const std::exception& e) {  // a malformed answer: the tab gives up, which counts
        load.recorder.error(kind, std::string("a tab stopped: ") + e.what());
      }
    });
  }

  const auto [rss_mib, threads] =
      sample_server(server, load, start, [&] { return std::to_string(load.runs_ended.load()) + " runs ended, "; });
  for (auto& t : tabs) t.join();  // each finishes the request it had begun
  const double held = std::chrono::duration<double>(Clock::now() - start).count();

  for (const Session& s : owner_sessions)  // designs are interrupted on SIGTERM anyway; ask first, as a user
    setup->Post("/api/projects/load/designs/stop", s.headers(), "{}", "application/json");
  const std::string exit = server.stop();

  json doc = load.recorder.document(kLoadKinds);
  doc["clients"] = {{"total", o.clients}, {"sign-in", signin}, {"parse", parse}, {"exec", exec}, {"monitor", monitor}};
  doc["seconds"] = o.seconds;
  doc["held_seconds"] = held;
  doc["keep_alive"] = o.keep_alive;
  doc["designs"] = designs;
  doc["runs_ended"] = load.runs_ended.load();
  doc["rss_mib"] = rss_mib;
  doc["threads"] = threads;
  const auto warmup = static_cast<std::size_t>(o.warmup);
  doc["rss"] = rss_verdict(rss_mib, warmup);
  doc["rss"]["warmup_s"] = o.warmup;
  doc["server_exit"] = exit;
  const long errors = count_errors(doc);

  if (o.json) {
    std::cout << doc.dump(1) << "\n";
  } else {
    std::printf("%d clients (%d sign-in, %d parse, %d exec, %d monitor) for %.0f s, keep-alive %s, %d designs running\n",
                o.clients, signin, parse, exec, monitor, held, o.keep_alive ? "on" : "off", designs);
    print_kinds(doc, kLoadKinds);
    std::printf("Exec runs ended: %ld; errors: %ld; server %s\n", load.runs_ended.load(), errors, exit.c_str());
    std::printf("server RSS (MiB) / threads, one sample per second:\n");
    for (std::size_t i = 0; i < rss_mib.size(); ++i)
      std::printf("%s%6.1f/%ld%s", i % 10 == 0 ? "  " : " ", rss_mib[i], threads[i],
                  i % 10 == 9 || i + 1 == rss_mib.size() ? "\n" : "");
    const json& v = doc["rss"];
    if (v["flat"].is_null())
      std::printf("RSS: %s\n", v["note"].get<std::string>().c_str());
    else
      std::printf("RSS after %.0f s of warm-up: first quarter %.1f MiB, last quarter %.1f MiB (floors): %+.1f MiB "
                  "(%+.1f %%): %s\n",
                  o.warmup, v["first_quarter_mib"].get<double>(), v["last_quarter_mib"].get<double>(),
                  v["growth_mib"].get<double>(), v["growth_percent"].get<double>(), v["flat"].get<bool>() ? "flat" : "GROWS");
  }
  const bool flat = doc["rss"]["flat"].is_boolean() && doc["rss"]["flat"].get<bool>();
  return errors == 0 && flat && exit == "exit 0" ? 0 : 1;
}

// --- The lab (--lab, issue #56) -------------------------------------------------------------

/// An answer of the API: its status (0: none), its JSON body (discarded when not JSON), how it
/// reads in an error message and how long it took.
struct Answer {
  int status = 0;
  json body;
  std::string text;
  double ms = 0;
  std::string error() const { return body.is_object() && body.contains("error") ? body.value("error", "") : ""; }
};

Answer ask(httplib::Client& c, const Session& s, const std::string& path, const json* post = nullptr) {
  const auto start = Clock::now();
  const auto r = post ? c.Post(path.c_str(), s.headers(), post->dump(), "application/json") : c.Get(path.c_str(), s.headers());
  Answer a;
  a.ms = ms_since(start);
  a.text = describe(r);
  if (r) {
    a.status = r->status;
    a.body = json::parse(r->body, nullptr, false);
  }
  return a;
}
Answer post(httplib::Client& c, const Session& s, const std::string& path, const json& body) { return ask(c, s, path, &body); }

/// One account of the lab: its designs' projects ("design1", "design2", ...), their ids, and
/// which of them run during the measured time.
struct LabAccount {
  std::string name;
  Session session;
  std::vector<std::string> projects;
  std::vector<std::int64_t> design_ids;
  std::vector<char> running;  // written before the tabs start, read by them
};

/// The design monitor of one account: every `poll` seconds each of its designs' status, as the
/// page's monitor polls the design it shows (without the race log). A design resumed for the measured time must be
/// running in this server at every poll.
void lab_monitor_tab(Load& load, const LabAccount& a, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  while (load.running()) {
    for (std::size_t d = 0; d < a.projects.size() && load.running(); ++d) {
      const Answer r = ask(*c, a.session, "/api/projects/" + a.projects[d] + "/status?race_log=false");
      const bool whole = r.status == 200 && r.body.is_object() && r.body.contains("running_here") &&
                         r.body.contains("design") && r.body.at("design").is_object();
      if (!whole) {
        load.recorder.error(kStatus, r.text);
        continue;
      }
      const std::string state = r.body.at("design").value("state", "");
      if (a.running[d] && (!r.body.value("running_here", false) || state != "running"))
        load.recorder.error(kStatus, a.name + "/" + a.projects[d] + ": a resumed design no longer runs here (" + state + ")");
      else
        load.recorder.ok(kStatus, r.ms);
    }
    load.pause(load.options.poll, random);
  }
}

double process_cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// CPU seconds the whole machine has been busy (every core, /proc/stat's first line: all but idle and iowait).
double machine_busy_seconds() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  return (user + nice + system + irq + softirq + steal) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

/// /proc/loadavg's 1, 5 and 15 minute figures: how busy the machine was besides the bench.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

int run_lab(const Options& o) {
  if (o.lab_signin_pause.size() != 2 || o.lab_signin_pause[0] < 0 || o.lab_signin_pause[1] < o.lab_signin_pause[0])
    throw std::runtime_error("--lab-signin-pause takes two numbers of seconds: least,most");
  const int n = o.accounts, per = o.designs_per_account;
  const long long budget = o.budget, quota = per * o.budget;

  Server server(o.binary);
  std::vector<LabAccount> accounts(static_cast<std::size_t>(n));
  progress("signing up " + std::to_string(n) + " accounts (lab0, the first, is the administrator)");
  for (int i = 0; i < n; ++i) {
    LabAccount& a = accounts[static_cast<std::size_t>(i)];
    a.name = "lab" + std::to_string(i);
    server.sign_up(a.name);
    for (int d = 0; d < per; ++d) a.projects.push_back("design" + std::to_string(d + 1));
    a.design_ids.assign(static_cast<std::size_t>(per), 0);
    a.running.assign(static_cast<std::size_t>(per), 0);
  }
  // The administrator at the terminal: the server's default quota, which every account follows.
  const json set = json::parse(server.cli("lab0", "admin quota --default --runs-per-day " + std::to_string(quota) + " --json"),
                               nullptr, false);
  if (!set.is_object() || set.value("runs_per_day", json()) != json(quota))
    throw std::runtime_error("admin quota --default did not set runs_per_day " + std::to_string(quota) + ": " + set.dump());
  progress("server default quota: " + std::to_string(quota) + " runs per day (" + std::to_string(per) + " designs of " +
           std::to_string(budget) + ")");
  server.start();
  progress("server on port " + std::to_string(server.port()));

  Load load{o, server.port(), {}, {}, {}, {}, {}};
  Recorder& recorder = load.recorder;
  auto setup = connect(server.port(), true);
  for (LabAccount& a : accounts) a.session = sign_in(*setup, a.name);
  {
    const Answer r = ask(*setup, accounts[0].session, "/api/admin/quota");
    if (r.status != 200 || !r.body.is_object() || r.body.value("runs_per_day", json()) != json(quota))
      throw std::runtime_error("GET /api/admin/quota as lab0: " + r.text);
  }

  const std::string over = "over-quota";  // the project of each account's design too many
  const auto design_body = [](int seed) { return json{{"architectures", "fsm"}, {"flavours", "chocolate"}, {"seed", seed}}; };
  long over_quota_refusals = 0, quota_reads_right = 0;
  std::string quota_message, server_full_message;
  // The design too many: refused by the runs quota, before anything else (even with the
  // account's designs, or the server's, all running).
  const auto third_design = [&](const LabAccount& a) {
    const Answer r = post(*setup, a.session, "/api/projects/" + over + "/designs", design_body(1000));
    if (r.status == 409 && r.error().rfind("runs quota:", 0) == 0) {
      recorder.refused(kOverQuota, r.ms);
      ++over_quota_refusals;
      if (quota_message.empty()) quota_message = r.error();
    } else {
      recorder.error(kOverQuota, a.name + ": " + r.text);
    }
  };
  const auto read_quota = [&](const LabAccount& a) {
    const Answer r = ask(*setup, a.session, "/api/quota");
    if (r.status == 200 && r.body.is_object() && r.body.value("runs_today", json()) == json(quota) &&
        r.body.value("runs_per_day", json()) == json(quota) && r.body.value("runs_from_default", false)) {
      recorder.ok(kQuota, r.ms);
      ++quota_reads_right;
    } else {
      recorder.error(kQuota, a.name + ": not runs_today " + std::to_string(quota) + " of the default " +
                                 std::to_string(quota) + ": " + r.text);
    }
  };
  // Until the project's design is interrupted (the stop lands within its race step's run).
  const auto wait_stopped = [&](const LabAccount& a, const std::string& project) {
    const auto until = Clock::now() + std::chrono::seconds(60);
    for (std::string state;;) {
      const Answer r = ask(*setup, a.session, "/api/projects/" + project + "/status?race_log=false");
      if (r.status == 200 && r.body.is_object() && r.body.contains("design") && r.body.at("design").is_object()) {
        state = r.body.at("design").value("state", "");
        if (state == "interrupted" && !r.body.value("running_here", true)) return;
      }
      if (Clock::now() > until) {
        recorder.error(kDesignStop, a.name + "/" + project + " still not interrupted after 60 s: " + r.text);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  };

  // Set-up, one account after another (so the server's limit of designs never refuses a start):
  // the projects, a design started in each, the design too many refused, the use read, then
  // the designs stopped (interrupted) for the next account.
  for (int i = 0; i < n; ++i) {
    LabAccount& a = accounts[static_cast<std::size_t>(i)];
    std::vector<std::string> projects = a.projects;
    projects.push_back(over);
    for (const std::string& p : projects) {
      const Answer r = post(*setup, a.session, "/api/projects", {{"name", p}, {"mission", "aac"}, {"budget", budget}});
      if (r.status != 200) throw std::runtime_error(a.name + ": new project " + p + ": " + r.text);
      recorder.ok(kProject, r.ms);
    }
    for (int d = 0; d < per; ++d) {
      const auto k = static_cast<std::size_t>(d);
      const Answer r = post(*setup, a.session, "/api/projects/" + a.projects[k] + "/designs", design_body(i * per + d + 1));
      if (r.status != 200 || !r.body.is_object() || !r.body.contains("id"))
        throw std::runtime_error(a.name + ": start a design in " + a.projects[k] + ": " + r.text);
      recorder.ok(kDesignStart, r.ms);
      a.design_ids[k] = r.body.at("id").get<std::int64_t>();
    }
    third_design(a);
    read_quota(a);
    for (const std::string& p : a.projects) {
      const Answer r = post(*setup, a.session, "/api/projects/" + p + "/designs/stop", json::object());
      if (r.status == 200 && r.body.is_object() && r.body.value("stopping", false)) recorder.ok(kDesignStop, r.ms);
      else recorder.error(kDesignStop, a.name + "/" + p + ": " + r.text);
    }
    for (const std::string& p : a.projects) wait_stopped(a, p);
    if ((i + 1) % 5 == 0 || i + 1 == n) progress("set up " + std::to_string(i + 1) + " of " + std::to_string(n) + " accounts");
  }

  // Every design resumed, account after account, as far as the server takes them: its own
  // limit refuses the rest (409), which is not a quota's doing. A resume counts no runs.
  // --running-designs N stops at N (0: no design runs while the tabs are measured).
  int running = 0, refused_by_server = 0;
  for (LabAccount& a : accounts) {
    for (int d = 0; d < per; ++d) {
      const auto k = static_cast<std::size_t>(d);
      if (o.running_designs >= 0 && running >= o.running_designs) break;
      const int seed = static_cast<int>(&a - accounts.data()) * per + d + 1;
      const Answer r = post(*setup, a.session, "/api/projects/" + a.projects[k] + "/designs", design_body(seed));
      if (r.status == 200 && r.body.is_object() && r.body.value("id", json()) == json(a.design_ids[k]) &&
          r.body.value("state", "") == "running") {
        recorder.ok(kDesignResume, r.ms);
        a.running[k] = 1;
        ++running;
      } else if (r.status == 409 && r.error().rfind("this server runs", 0) == 0) {
        recorder.refused(kDesignResume, r.ms);
        ++refused_by_server;
        if (server_full_message.empty()) server_full_message = r.error();
      } else {
        recorder.error(kDesignResume, a.name + "/" + a.projects[k] + ": " + r.text);
      }
    }
  }
  for (const LabAccount& a : accounts) read_quota(a);
  progress(std::to_string(running) + " designs running, " + std::to_string(refused_by_server) +
           " resumes refused by the server's limit" + (server_full_message.empty() ? "" : " (\"" + server_full_message + "\")"));

  const auto start = Clock::now();
  load.end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  const double server_cpu_start = server.cpu_seconds(), bench_cpu_start = process_cpu_seconds();
  const std::string load_before = load_average();
  const double machine_start = machine_busy_seconds();
  progress(std::to_string(n) + " accounts x (1 monitor tab + 1 sign-in tab) for " + std::to_string(static_cast<int>(o.seconds)) + " s");
  std::vector<std::thread> tabs;
  for (int i = 0; i < 2 * n; ++i) {
    tabs.emplace_back([&, i] {
      std::mt19937 random(static_cast<unsigned>(i) * 7919u + 1u);
      const LabAccount& a = accounts[static_cast<std::size_t>(i / 2)];
      const Kind kind = i % 2 == 0 ? kStatus : kSignIn;
      // The monitors open over the first second; the sign-in tabs' first rounds spread over
      // their longest pause, as users who do not all arrive at once (no burst of checks at 0 s).
      if (kind == kStatus) std::this_thread::sleep_for(std::chrono::milliseconds(random() % 1000));
      else load.pause_between(0, o.lab_signin_pause[1], random);
      try {
        if (kind == kStatus) lab_monitor_tab(load, a, random);
        else sign_in_tab(load, a.name, o.lab_signin_pause[0], o.lab_signin_pause[1], random);
      } catch (const std::exception& e) {
        load.recorder.error(kind, std::string("a tab stopped: ") + e.what());
      }
    });
  }
  const auto [rss_mib, threads] = sample_server(server, load, start, [] { return std::string(); });
  for (auto& t : tabs) t.join();
  const double held = std::chrono::duration<double>(Clock::now() - start).count();
  const double server_cpu = server.cpu_seconds() - server_cpu_start, bench_cpu = process_cpu_seconds() - bench_cpu_start;
  const std::string load_after = load_average();
  const double machine_busy = machine_busy_seconds() - machine_start;

  // After the load: the quota still refuses the design too many, the use is still the two designs'.
  for (const LabAccount& a : accounts) {
    third_design(a);
    read_quota(a);
  }
  for (const LabAccount& a : accounts)  // designs are interrupted on SIGTERM anyway; ask first, as a user
    for (std::size_t k = 0; k < a.projects.size(); ++k)
      if (a.running[k]) {
        const Answer r = post(*setup, a.session, "/api/projects/" + a.projects[k] + "/designs/stop", json::object());
        if (r.status == 200) recorder.ok(kDesignStop, r.ms);
        else recorder.error(kDesignStop, a.name + "/" + a.projects[k] + ": " + r.text);
      }
  setup.reset();
  const std::string exit = server.stop();

  const std::vector<Kind> kinds{kSignIn, kSession,   kSignOut,   kStatus,     kProject,
                                kDesignStart, kOverQuota, kQuota, kDesignStop, kDesignResume};
  json doc = recorder.document(kinds);
  doc["scenario"] = "lab";
  doc["accounts"] = n;
  doc["designs_per_account"] = per;
  doc["budget"] = budget;
  doc["runs_per_day"] = quota;
  doc["seconds"] = o.seconds;
  doc["held_seconds"] = held;
  doc["keep_alive"] = o.keep_alive;
  doc["signin_pause_s"] = o.lab_signin_pause;
  doc["poll_s"] = o.poll;
  doc["designs"] = {{"started", n * per},
                    {"running", running},
                    {"refused_by_server", refused_by_server},
                    {"server_limit_message", server_full_message}};
  const long quota_refusals_expected = 2L * n, quota_reads_expected = 3L * n;
  const bool quotas_hold = over_quota_refusals == quota_refusals_expected && quota_reads_right == quota_reads_expected;
  doc["quotas"] = {{"over_quota_refused", over_quota_refusals},
                   {"over_quota_expected", quota_refusals_expected},
                   {"reads_right", quota_reads_right},
                   {"reads_expected", quota_reads_expected},
                   {"message", quota_message},
                   {"hold", quotas_hold}};
  json verdict = json::object();
  bool fast = true;
  for (const Kind k : {kSignIn, kStatus}) {
    const json& r = doc["kinds"][kKindNames[k]];
    const bool holds = r["answers"].get<long>() > 0 && r["p95_ms"].get<double>() <= o.p95_target_ms;
    fast = fast && holds;
    verdict[kKindNames[k]] = {{"p95_ms", r["p95_ms"]}, {"target_ms", o.p95_target_ms}, {"holds", holds}};
  }
  doc["verdict"] = verdict;
  doc["server_cpu_percent"] = 100.0 * server_cpu / held;
  doc["bench_cpu_percent"] = 100.0 * bench_cpu / held;
  doc["load_average"] = {{"start", load_before}, {"end", load_after}};
  // What the rest of the machine took meanwhile (other processes: a build, tests): the figures
  // are this scenario's only when it is near 0.
  doc["others_cpu_percent"] = 100.0 * std::max(0.0, machine_busy - server_cpu - bench_cpu) / held;
  doc["rss_mib"] = rss_mib;
  doc["threads"] = threads;
  if (!rss_mib.empty()) {
    std::vector<double> sorted = rss_mib;
    std::sort(sorted.begin(), sorted.end());
    doc["rss"] = {{"min_mib", sorted.front()}, {"median_mib", sorted[sorted.size() / 2]}, {"max_mib", sorted.back()},
                  {"first_mib", rss_mib.front()}, {"last_mib", rss_mib.back()}};
  }
  doc["server_exit"] = exit;
  const long errors = count_errors(doc);

  if (o.json) {
    std::cout << doc.dump(1) << "\n";
  } else {
    std::printf("lab: %d accounts x %d designs (AAC, FSM, Chocolate, budget %lld each; server default quota %lld runs "
                "per day) for %.0f s, keep-alive %s\n",
                n, per, budget, quota, held, o.keep_alive ? "on" : "off");
    std::printf("designs: %d started (then stopped) at set-up; %d resumed and running during the measured time%s, %d "
                "resumes refused by the server%s%s%s\n",
                n * per, running, o.running_designs >= 0 ? " (--running-designs)" : "", refused_by_server, server_full_message.empty() ? "" : " (\"",
                server_full_message.c_str(), server_full_message.empty() ? "" : "\")");
    std::printf("tabs: %d design monitors (each design's status every %.1f s) and %d sign-in tabs (sign in, session, "
                "sign out, every %.1f-%.1f s)\n",
                n, o.poll, n, o.lab_signin_pause[0], o.lab_signin_pause[1]);
    print_kinds(doc, kinds);
    std::printf("quotas: %ld of %ld designs too many refused with \"runs quota: ...\" (at set-up and after the load), "
                "%ld of %ld reads of /api/quota at runs_today %lld of the default %lld: %s\n",
                over_quota_refusals, quota_refusals_expected, quota_reads_right, quota_reads_expected, quota, quota,
                quotas_hold ? "holding" : "NOT HOLDING");
    if (!quota_message.empty()) std::printf("  e.g. %s\n", quota_message.c_str());
    for (const Kind k : {kSignIn, kStatus})
      std::printf("p95 %s: %.1f ms <= %.0f ms: %s\n", kKindNames[k], verdict[kKindNames[k]]["p95_ms"].get<double>(),
                  o.p95_target_ms, verdict[kKindNames[k]]["holds"].get<bool>() ? "yes" : "NO");
    std::printf("CPU over the measured time, %% of one core: server %.0f, this bench %.0f, other processes %.0f (load "
                "average %s at the start, %s at the end); server %s; errors: %ld\n",
                doc["server_cpu_percent"].get<double>(), doc["bench_cpu_percent"].get<double>(),
                doc["others_cpu_percent"].get<double>(), load_before.c_str(), load_after.c_str(), exit.c_str(), errors);
    if (doc.contains("rss"))
      std::printf("server RSS (MiB): first %.1f, min %.1f, median %.1f, max %.1f, last %.1f; threads %ld-%ld\n",
                  doc["rss"]["first_mib"].get<double>(), doc["rss"]["min_mib"].get<double>(),
                  doc["rss"]["median_mib"].get<double>(), doc["rss"]["max_mib"].get<double>(),
                  doc["rss"]["last_mib"].get<double>(), *std::min_element(threads.begin(), threads.end()),
                  *std::max_element(threads.begin(), threads.end()));
  }
  return errors == 0 && quotas_hold && fast && exit == "exit 0" ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"HTTP under load: N concurrent clients against one real `swarmdesign run-exp` on loopback"};
  app.add_option("--clients", o.clients, "concurrent clients (tabs)")->check(CLI::Range(4, 2000))->capture_default_str();
  app.add_option("--seconds", o.seconds, "how long the clients are held")->check(CLI::Range(5.0, 3600.0))->capture_default_str();
  app.add_option("--warmup", o.warmup, "seconds of RSS not judged for flatness")->check(CLI::Range(0.0, 3600.0))->capture_default_str();
  app.add_option("--mix", o.mix, "percent of clients: sign-in,parse,exec,monitor")->delimiter(',')->expected(4)->capture_default_str();
  app.add_option("--designs", o.designs, "background designs the monitors watch")->check(CLI::Range(1, 8))->capture_default_str();
  app.add_option("--signin-pause", o.signin_pause, "seconds between a sign-in tab's rounds")->capture_default_str();
  app.add_option("--parse-pause", o.parse_pause, "seconds between a parse tab's requests")->capture_default_str();
  app.add_option("--exec-pause", o.exec_pause, "seconds between an exec tab's runs")->capture_default_str();
  app.add_option("--poll", o.poll, "seconds between a monitor's polls")->capture_default_str();
  app.add_flag("!--no-keep-alive", o.keep_alive, "a new connection per request (keep-alive is on, as in browsers)");
  app.add_flag("--json", o.json, "print the figures as JSON instead of the table");
  app.add_option("--binary", o.binary, "the swarmdesign binary")->capture_default_str();
  app.add_flag("--lab", o.lab,
               "the lab instead (issue #56): accounts with designs under a runs quota, each with a design monitor "
               "and a sign-in tab; p95 of sign-in and status against --p95-target");
  app.add_option("--accounts", o.accounts, "--lab: accounts (the first is the administrator)")
      ->check(CLI::Range(1, 500))->capture_default_str();
  app.add_option("--designs-per-account", o.designs_per_account,
                 "--lab: designs each account starts (the server runs at most 2 per user)")
      ->check(CLI::Range(1, 2))->capture_default_str();
  app.add_option("--budget", o.budget, "--lab: each design's budget (runs); the quota is designs-per-account x budget")
      ->check(CLI::Range(1LL, 1000000000LL))->capture_default_str();
  app.add_option("--lab-signin-pause", o.lab_signin_pause, "--lab: seconds between a sign-in tab's rounds: least,most")
      ->delimiter(',')->expected(2)->capture_default_str();
  app.add_option("--running-designs", o.running_designs,
                 "--lab: designs resumed for the measured time (-1: as many as the server takes; 0: none, a baseline)")
      ->check(CLI::Range(-1, 100000))->capture_default_str();
  app.add_option("--p95-target", o.p95_target_ms, "--lab: the p95 (ms) sign-in and status must keep")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    if (o.lab) return run_lab(o);
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "load_bench: " << e.what() << "\n";
    return 2;
  }
}
