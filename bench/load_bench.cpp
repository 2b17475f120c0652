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
// from an earlier run of the same seed) and the latency's p50, p99 and max; it samples the
// server's RSS (/proc) every second and says whether it stays flat after the warm-up.
// Run: ./build/bench/load_bench [--clients 200] [--seconds 60] [--json]   (see --help)
#include <CLI/CLI.hpp>
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
};

enum Kind { kSignIn, kSession, kSignOut, kParse, kExecStart, kExecFirstFrame, kExecEnd, kStatus, kDesigns, kKinds };
const char* const kKindNames[kKinds] = {"sign-in",         "session",       "sign-out",       "parse",  "exec-start",
                                        "exec-first-frame", "exec-whole-run", "monitor-status", "monitor-designs"};

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
  json document() const;

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

json Recorder::document() const {
  std::lock_guard lock(mutex_);
  json kinds = json::object();
  for (int k = 0; k < kKinds; ++k) {
    const std::vector<double>& v = ms_[k];
    kinds[kKindNames[k]] = {{"answers", v.size()},
                            {"refused", refused_[k]},
                            {"errors", errors_[k]},
                            {"p50_ms", percentile(v, 50)},
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
  void pause(double seconds, std::mt19937& random) const {
    std::uniform_real_distribution<double> jitter(0.75, 1.25);
    const auto until = std::min(end, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                         std::chrono::duration<double>(seconds * jitter(random))));
    std::this_thread::sleep_until(until);
  }
};

void sign_in_tab(Load& load, const std::string& name, std::mt19937& random) {
  auto c = connect(load.port, load.options.keep_alive);
  while (load.running()) {
    auto start = Clock::now();
    const auto in = c->Post("/api/sign-in", json{{"name", name}, {"password", kPassword}}.dump(), "application/json");
    if (!in || in->status != 200 || in->get_header_value("Set-Cookie").empty()) {
      load.recorder.error(kSignIn, describe(in));
      load.pause(load.options.signin_pause, random);
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
    load.pause(load.options.signin_pause, random);
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
    const auto r = c->Get(("/api/projects/" + project + "/status").c_str(), s.headers());
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
  auto progress = [&](const std::string& what) {
    std::cerr << "load_bench: " << what << std::endl;  // stderr: --json's stdout stays JSON
  };
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
        if (i < signin) sign_in_tab(load, "signin" + std::to_string(i), random);
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

  std::vector<double> rss_mib;
  std::vector<long> threads;
  for (int s = 0; Clock::now() < load.end; ++s) {
    const auto [rss, n] = server.rss_kib_and_threads();
    rss_mib.push_back(static_cast<double>(rss) / 1024.0);
    threads.push_back(n);
    if (s % 10 == 0)
      progress("t=" + std::to_string(s) + " s: RSS " + std::to_string(static_cast<int>(rss_mib.back())) + " MiB, " +
               std::to_string(n) + " threads, " + std::to_string(load.runs_ended.load()) + " runs ended, " +
               std::to_string(load.recorder.total_errors()) + " errors");
    std::this_thread::sleep_until(start + std::chrono::seconds(s + 1));
  }
  for (auto& t : tabs) t.join();  // each finishes the request it had begun
  const double held = std::chrono::duration<double>(Clock::now() - start).count();

  for (const Session& s : owner_sessions)  // designs are interrupted on SIGTERM anyway; ask first, as a user
    setup->Post("/api/projects/load/designs/stop", s.headers(), "{}", "application/json");
  const std::string exit = server.stop();

  json doc = load.recorder.document();
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
  long errors = 0;
  for (const auto& [name, k] : doc["kinds"].items()) errors += k["errors"].get<long>();
  doc["errors"] = errors;

  if (o.json) {
    std::cout << doc.dump(1) << "\n";
  } else {
    std::printf("%d clients (%d sign-in, %d parse, %d exec, %d monitor) for %.0f s, keep-alive %s, %d designs running\n",
                o.clients, signin, parse, exec, monitor, held, o.keep_alive ? "on" : "off", designs);
    std::printf("%-17s %8s %8s %7s %9s %9s %9s\n", "kind", "answers", "refused", "errors", "p50 ms", "p99 ms", "max ms");
    for (int k = 0; k < kKinds; ++k) {
      const json& r = doc["kinds"][kKindNames[k]];
      std::printf("%-17s %8ld %8ld %7ld %9.1f %9.1f %9.1f\n", kKindNames[k], r["answers"].get<long>(),
                  r["refused"].get<long>(), r["errors"].get<long>(), r["p50_ms"].get<double>(),
                  r["p99_ms"].get<double>(), r["max_ms"].get<double>());
    }
    for (const auto& [what, n] : doc["error_messages"].items()) std::printf("  %ld x %s\n", n.get<long>(), what.c_str());
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
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "load_bench: " << e.what() << "\n";
    return 2;
  }
}
