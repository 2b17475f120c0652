// The web server as an attacker with an account meets it, over loopback HTTP against the real
// server in this process, with two accounts: no path a user types reaches a file outside their
// own projects (absolute, "..", a planted link, a device, another user's file), refusals look
// the same whether the file exists or not and never quote it, reads are bounded, sign-in gives
// away neither names (answer and time) nor unlimited guesses, a foreign Host is refused, and
// one user cannot take every Exec slot.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>
#include <vector>

#include "app/accounts.hpp"
#include "app/errors.hpp"
#include "storage/projects.hpp"
#include "web/host_check.hpp"
#include "web/http_io.hpp"
#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

const std::string kOneStateFsm = "--fsm-config --nstates 1 --s0 0 --rwm0 50";
const std::string kSecret = "SECRET-8d1f0c";  // in files no refusal may quote

/// Resident memory of this process, in MiB.
double resident_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

class WebSecurity : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("sd-websec-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
    {
      app::Home home(root_ / "home");
      app::sign_up(home, "alice", "alice-password");
      app::sign_up(home, "bob", "bob-password");
    }
  }
  void TearDown() override {
    alice_.reset();
    bob_.reset();
    server_.reset();
    std::filesystem::remove_all(root_);
  }

  void serve(storage::SignInPolicy policy = {}, std::vector<std::string> allowed_hosts = {}) {
    server_.emplace(web::WebServerOptions{"127.0.0.1", 0, {}, root_ / "home", std::move(allowed_hosts), policy, false});
    alice_.emplace(server_->port());
    bob_.emplace(server_->port());
    ASSERT_TRUE(alice_->sign_in("alice", "alice-password")) << alice_->last_refusal();
    ASSERT_TRUE(bob_->sign_in("bob", "bob-password")) << bob_->last_refusal();
  }

  std::filesystem::path projects_of(const std::string& user) { return root_ / "home" / "users" / user / "projects"; }

  /// A project of `user` made over the web on a short AAC file put in its folder first.
  std::string project_with_own_mission(WebClient& client, const std::string& user, const std::string& name) {
    const auto folder = projects_of(user) / name;
    std::filesystem::create_directories(folder);
    const std::string mission = write_short_mission(folder).string();
    const Answer a = client.post("/api/projects", {{"name", name}, {"mission", mission}, {"budget", "300"}});
    EXPECT_EQ(a.status, 200) << a.text;
    return mission;
  }

  /// What every route that takes a mission answers for `path`: creating a project, Exec, drawing.
  std::vector<Answer> mission_answers(WebClient& client, const std::string& path) {
    return {client.post("/api/projects", {{"name", "probe"}, {"mission", path}, {"budget", "300"}}),
            client.post("/api/runs", {{"text", kOneStateFsm}, {"mission", path}, {"seed", 1}}),
            client.get("/api/missions/svg?name=" + path)};
  }

  /// The refusal with the path taken out: what must be the same for every forbidden file.
  static std::string words_without(const Answer& a, const std::string& path) {
    std::string words = a.body.is_object() ? a.body.value("error", a.text) : a.text;
    std::string out = std::to_string(a.status);
    out.push_back(' ');
    for (std::size_t from = 0;;) {  // every occurrence of the path becomes "P"
      const std::size_t at = words.find(path, from);
      out.append(words, from, at == std::string::npos ? std::string::npos : at - from);
      if (at == std::string::npos) return out;
      out.push_back('P');
      from = at + path.size();
    }
  }

  void expect_refused_like_a_missing_file(WebClient& client, const std::string& path) {
    const std::string missing = (root_ / "no-such-file.json").string();
    const auto reference = mission_answers(client, missing);
    const auto answers = mission_answers(client, path);
    // A path in the server's home is quoted as its user would name it, never with the home's folder.
    const std::string quoted = web::without_server_paths(path, (root_ / "home").string());
    for (std::size_t i = 0; i < answers.size(); ++i) {
      EXPECT_EQ(answers[i].status, 404) << path << ": " << answers[i].text;
      EXPECT_EQ(words_without(answers[i], quoted), words_without(reference[i], missing)) << path;
      EXPECT_EQ(answers[i].text.find((root_ / "home").string()), std::string::npos) << "the server's home in: " << answers[i].text;
      EXPECT_EQ(answers[i].text.find(kSecret), std::string::npos) << "a refusal quoted the file: " << answers[i].text;
    }
  }

  std::filesystem::path root_;
  std::optional<RunningServer> server_;
  std::optional<WebClient> alice_, bob_;
};

TEST(WebMessages, NoMessageCarriesTheServersFolders) {
  EXPECT_EQ(web::without_server_paths("mission file /srv/sd/users/ann/projects/lab/m.json is not valid", "/srv/sd"),
            "mission file users/ann/projects/lab/m.json is not valid");
  EXPECT_EQ(web::without_server_paths("cannot read /srv/sd/swarmdesign.db and /srv/sd/users/x", "/srv/sd/"),
            "cannot read swarmdesign.db and users/x");
  EXPECT_EQ(web::without_server_paths("/etc/passwd is not a file of your projects", "/srv/sd"),
            "/etc/passwd is not a file of your projects");
  EXPECT_EQ(web::without_server_paths("nothing here", ""), "nothing here");
}

TEST_F(WebSecurity, AFileOutsideOnesProjectsIsRefusedAlikeWhetherItExistsOrNot) {
  serve();
  // A readable file of the server's disk, as JSON and as text, each holding a secret.
  const auto outside = root_ / "outside";
  std::filesystem::create_directories(outside);
  std::ofstream(outside / "valid.json") << std::ifstream(std::filesystem::path(::sd::test::source_dir()) / "missions" / "aac.json").rdbuf();
  std::ofstream(outside / "secret.json") << "{\"name\": \"" << kSecret << "\", oops";
  for (const auto& path : {(outside / "valid.json").string(), (outside / "secret.json").string(), std::string("/etc/passwd"),
                           std::string("/etc/hostname"), std::string("/proc/self/environ"), (outside / "missing.json").string(),
                           std::string("relative/aac.json"), std::string("aac-short.json")})
    expect_refused_like_a_missing_file(*alice_, path);
  EXPECT_TRUE(alice_->get("/api/projects").body.empty()) << "no refused project may be left";
}

TEST_F(WebSecurity, AnotherUsersMissionFileIsOutOfReachByAbsolutePathAndByDotDot) {
  serve();
  const std::string bobs = project_with_own_mission(*bob_, "bob", "bobs");
  const std::string alices = project_with_own_mission(*alice_, "alice", "mine");
  // Bob's own file works for Bob.
  EXPECT_EQ(bob_->get("/api/missions/svg?name=" + bobs).status, 200);

  expect_refused_like_a_missing_file(*alice_, bobs);
  const std::string dotdot = (projects_of("alice") / "mine" / ".." / ".." / ".." / "bob" / "projects" / "bobs" /
                              std::filesystem::path(bobs).filename()).string();
  expect_refused_like_a_missing_file(*alice_, dotdot);
  // Her own file through ".." that stays inside her projects is hers.
  const std::string inside = (projects_of("alice") / "mine" / ".." / "mine" / std::filesystem::path(alices).filename()).string();
  EXPECT_EQ(alice_->get("/api/missions/svg?name=" + inside).status, 200);

  for (const json& m : alice_->get("/api/missions").body) EXPECT_NE(m.at("name"), bobs);
  // A project that once named Bob's file (stored before this rule, or by the CLI) is not runnable
  // over the web either: it is not listed, and a design of it is refused.
  {
    app::Home home(root_ / "home");
    storage::Projects(home.workspace(), app::sign_in_here(home, "alice", "alice-password").user).set_mission(bobs);
  }
  for (const json& m : alice_->get("/api/missions").body) EXPECT_NE(m.at("name"), bobs);
  const Answer design = alice_->post("/api/projects/mine/designs", json::object());
  EXPECT_EQ(design.status, 404) << design.text;
}

TEST_F(WebSecurity, ALinkPlantedInOnesOwnProjectDoesNotLeadOut) {
  serve();
  const std::string bobs = project_with_own_mission(*bob_, "bob", "bobs");
  const std::string mine = project_with_own_mission(*alice_, "alice", "mine");
  const auto folder = projects_of("alice") / "mine";
  std::ofstream(root_ / "secret.json") << "{\"name\": \"" << kSecret << "\"}";
  std::filesystem::create_symlink(root_ / "secret.json", folder / "to-secret.json");
  std::filesystem::create_symlink(bobs, folder / "to-bob.json");
  std::filesystem::create_symlink("/dev/zero", folder / "to-zero.json");
  std::filesystem::create_symlink(root_, folder / "up");
  for (const auto& link : {folder / "to-secret.json", folder / "to-bob.json", folder / "to-zero.json", folder / "up" / "secret.json"})
    expect_refused_like_a_missing_file(*alice_, link.string());
  // A link that stays inside her projects is fine.
  std::filesystem::create_symlink(mine, folder / "alias.json");
  EXPECT_EQ(alice_->get("/api/missions/svg?name=" + (folder / "alias.json").string()).status, 200);

  // Saved control software is read under the same rule: a planted .txt link is not read.
  ASSERT_EQ(alice_->post("/api/projects/mine/software", {{"name", "walker"}, {"text", kOneStateFsm}}).status, 200);
  std::ofstream(root_ / "secret.txt") << kSecret;
  std::filesystem::create_symlink(root_ / "secret.txt", folder / "software" / "stolen.txt");
  std::filesystem::create_symlink("/dev/urandom", folder / "software" / "noise.txt");
  const Answer saved = alice_->get("/api/projects/mine/software");
  ASSERT_EQ(saved.status, 200) << saved.text;
  ASSERT_EQ(saved.body.size(), 1u) << saved.text;
  EXPECT_EQ(saved.body[0].at("name"), "walker");
  EXPECT_EQ(saved.text.find(kSecret), std::string::npos);
  // And no write follows a planted folder link out of her projects.
  std::filesystem::create_directories(projects_of("alice") / "other");
  std::filesystem::create_directories(root_ / "elsewhere");
  std::filesystem::create_symlink(root_ / "elsewhere", projects_of("alice") / "other" / "software");
  {
    app::Home home(root_ / "home");
    storage::Projects(home.workspace(), app::sign_in_here(home, "alice", "alice-password").user).create("other", std::nullopt);
  }
  EXPECT_EQ(alice_->post("/api/projects/other/software", {{"name", "w"}, {"text", kOneStateFsm}}).status, 404);
  EXPECT_TRUE(std::filesystem::is_empty(root_ / "elsewhere"));
  // Nor does a link to a folder that does not exist yet get that folder made.
  std::filesystem::remove(projects_of("alice") / "other" / "software");
  std::filesystem::create_symlink(root_ / "not-yet", projects_of("alice") / "other" / "software");
  EXPECT_EQ(alice_->post("/api/projects/other/software", {{"name", "w"}, {"text", kOneStateFsm}}).status, 404);
  EXPECT_FALSE(std::filesystem::exists(root_ / "not-yet"));
}

TEST_F(WebSecurity, AHardLinkPlantedInOnesOwnProjectIsNotRead) {
  serve();
  const std::string bobs = project_with_own_mission(*bob_, "bob", "bobs");
  project_with_own_mission(*alice_, "alice", "mine");
  const auto folder = projects_of("alice") / "mine";
  // A hard link resolves inside her folder: no link to follow, yet another user's file.
  std::ofstream(root_ / "secret.json") << "{\"name\": \"" << kSecret << "\"}";
  std::filesystem::create_hard_link(bobs, folder / "hard-bob.json");
  std::filesystem::create_hard_link(root_ / "secret.json", folder / "hard-secret.json");
  for (const auto& link : {folder / "hard-bob.json", folder / "hard-secret.json"})
    expect_refused_like_a_missing_file(*alice_, link.string());
  EXPECT_TRUE(alice_->get("/api/projects").body.size() == 1u) << "no project may be made on a hard link";
  // A project pointed at it by other means (the CLI) is neither listed nor designed.
  {
    app::Home home(root_ / "home");
    storage::Projects(home.workspace(), app::sign_in_here(home, "alice", "alice-password").user)
        .set_mission((folder / "hard-bob.json").string());
  }
  for (const json& m : alice_->get("/api/missions").body) EXPECT_NE(m.at("name"), (folder / "hard-bob.json").string());
  EXPECT_EQ(alice_->post("/api/projects/mine/designs", json::object()).status, 404);
  // Nor is a hard-linked file read as saved control software.
  std::ofstream(root_ / "secret.txt") << kSecret;
  std::filesystem::create_directories(folder / "software");
  std::filesystem::create_hard_link(root_ / "secret.txt", folder / "software" / "stolen.txt");
  const Answer saved = alice_->get("/api/projects/mine/software");
  ASSERT_EQ(saved.status, 200) << saved.text;
  EXPECT_TRUE(saved.body.empty()) << saved.text;
  // Bob's own file, with its one name, still works for him.
  std::filesystem::remove(folder / "hard-bob.json");
  EXPECT_EQ(bob_->get("/api/missions/svg?name=" + bobs).status, 200);
}

TEST_F(WebSecurity, WhatTheServerCreatesIsPrivateToItsOwner) {
  ::umask(022);  // a usual umask, which would leave files 0644 and folders 0755
  serve();
  ASSERT_EQ(alice_->post("/api/projects", {{"name", "fresh"}, {"mission", "aac"}, {"budget", "300"}}).status, 200);
  ASSERT_EQ(alice_->post("/api/projects/fresh/software", {{"name", "walker"}, {"text", kOneStateFsm}}).status, 200);
  const auto mode = [](const std::filesystem::path& p) {
    struct stat info {};
    EXPECT_EQ(::stat(p.c_str(), &info), 0) << p;
    return info.st_mode & 0777;
  };
  const auto project = projects_of("alice") / "fresh";
  EXPECT_EQ(mode(project), 0700u);
  EXPECT_EQ(mode(project / "software"), 0700u);
  EXPECT_EQ(mode(project / "software" / "walker.txt"), 0600u);
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root_ / "home")) {
    if (entry.is_symlink()) continue;
    EXPECT_EQ(mode(entry.path()) & 077, 0u) << entry.path() << " is open to others";
  }
}

TEST_F(WebSecurity, DevicesFifosAndHugeFilesAreRefusedAtOnceWithMemoryFlat) {
  serve();
  project_with_own_mission(*alice_, "alice", "mine");
  const auto folder = projects_of("alice") / "mine";
  const double before = resident_mib();
  for (const std::string device : {"/dev/zero", "/dev/urandom", "/dev/stdin", "/dev/tty"})
    expect_refused_like_a_missing_file(*alice_, device);
  // In her own folder a FIFO (which would block a plain open) and a 2 MiB file are refused
  // for what they are: they are hers, so saying so tells nothing.
  ASSERT_EQ(::mkfifo((folder / "fifo.json").c_str(), 0600), 0);
  for (const Answer& a : mission_answers(*alice_, (folder / "fifo.json").string())) {
    EXPECT_EQ(a.status, 400) << a.text;
    EXPECT_NE(a.text.find("not a regular file"), std::string::npos) << a.text;
  }
  {
    std::ofstream big(folder / "big.json");
    big << "{\"name\": \"big\", \"description\": \"" << std::string(2 << 20, 'x') << "\"}";
  }
  for (const Answer& a : mission_answers(*alice_, (folder / "big.json").string())) {
    EXPECT_EQ(a.status, 400) << a.text.substr(0, 200);
    EXPECT_NE(a.text.find("larger than 1 MiB"), std::string::npos) << a.text.substr(0, 200);
    EXPECT_LT(a.text.size(), 1000u);
  }
  // A malformed file of her own: the error says where, and quotes nothing of it.
  std::ofstream(folder / "typo.json") << "{\n  \"name\": \"" << kSecret << "\",\n  oops\n}";
  const Answer typo = alice_->post("/api/runs", {{"text", kOneStateFsm}, {"mission", (folder / "typo.json").string()}, {"seed", 1}});
  EXPECT_EQ(typo.status, 400);
  EXPECT_NE(typo.text.find("line 3, column 3"), std::string::npos) << typo.text;
  EXPECT_EQ(typo.text.find(kSecret), std::string::npos) << typo.text;
  EXPECT_EQ(typo.text.find("oops"), std::string::npos) << typo.text;
  EXPECT_LT(resident_mib() - before, 64.0) << "reading a device or a huge file must not grow the server";
  EXPECT_EQ(alice_->get("/api/session").status, 200);
}

TEST_F(WebSecurity, SignInTakesAsLongForAnUnknownNameAsForAWrongPassword) {
  serve({.failures_before_lockout = 1000, .lockout = std::chrono::seconds(60), .failures_per_address = 1000});
  WebClient guesser(server_->port());
  const auto median_ms = [&](const std::string& name) {
    std::vector<double> times;
    for (int i = 0; i < 10; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const auto r = guesser.raw().Post("/api/sign-in", json{{"name", name}, {"password", "not-the-password"}}.dump(),
                                        "application/json");
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      EXPECT_EQ(r->status, 401);
      EXPECT_EQ(json::parse(r->body).at("error"), "wrong user name or password");
    }
    std::sort(times.begin(), times.end());
    return (times[4] + times[5]) / 2;
  };
  const double unknown = median_ms("carol"), wrong = median_ms("alice");
  EXPECT_LT(std::max(unknown, wrong) / std::min(unknown, wrong), 2.0) << "unknown " << unknown << " ms, wrong " << wrong << " ms";
}

TEST_F(WebSecurity, RepeatedFailuresLockANameKnownOrNotThenARightPasswordWorksAgain) {
  serve({.failures_before_lockout = 3, .lockout = std::chrono::seconds(3), .failures_per_address = 1000});
  WebClient guesser(server_->port());
  const auto sign_in = [&](const std::string& name, const std::string& password) {
    return guesser.raw().Post("/api/sign-in", json{{"name", name}, {"password", password}}.dump(), "application/json");
  };
  for (const std::string name : {"alice", "nobody"}) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(sign_in(name, "wrong-password")->status, 401);
    const auto locked = sign_in(name, name == "alice" ? "alice-password" : "wrong-password");
    EXPECT_EQ(locked->status, 429) << name << ": even the right password waits out the lock";
    const int wait = std::stoi(locked->get_header_value("Retry-After"));
    EXPECT_GE(wait, 1);
    EXPECT_LE(wait, 3);
    EXPECT_NE(json::parse(locked->body).at("error").get<std::string>().find("try again in"), std::string::npos);
    if (name != "alice") continue;
    // The CLI of the same home shares the count (asked at once: a loaded machine once took
    // longer than the lock over "nobody"'s guesses, each an Argon2id hash).
    app::Home home(root_ / "home");
    EXPECT_THROW(app::sign_in_here(home, "alice", "alice-password"), app::TooManyAttempts);
  }
  // Another name and the other user are untouched.
  EXPECT_TRUE(WebClient(server_->port()).sign_in("bob", "bob-password"));
  std::this_thread::sleep_for(std::chrono::milliseconds(3100));
  EXPECT_EQ(sign_in("alice", "alice-password")->status, 200);
  EXPECT_EQ(sign_in("alice", "wrong-password")->status, 401) << "the count started again";
}

TEST_F(WebSecurity, ManyFailuresFromOneAddressLockItWhicheverNamesItTries) {
  serve({.failures_before_lockout = 1000, .lockout = std::chrono::seconds(2), .failures_per_address = 4});
  WebClient guesser(server_->port());
  for (const std::string name : {"ann", "ben", "cid", "dot"})
    EXPECT_EQ(guesser.raw().Post("/api/sign-in", json{{"name", name}, {"password", "guess-guess"}}.dump(), "application/json")->status,
              401);
  const auto locked =
      guesser.raw().Post("/api/sign-in", json{{"name", "alice"}, {"password", "alice-password"}}.dump(), "application/json");
  EXPECT_EQ(locked->status, 429);
  EXPECT_TRUE(locked->has_header("Retry-After"));
  std::this_thread::sleep_for(std::chrono::milliseconds(3100));
  EXPECT_TRUE(WebClient(server_->port()).sign_in("alice", "alice-password"));
}

TEST_F(WebSecurity, ARequestNamingAForeignHostIsRefused) {
  serve({}, {"lab.example.org"});
  const std::string port = std::to_string(server_->port());
  const std::string other_port = std::to_string(server_->port() + 1);
  httplib::Client raw("127.0.0.1", server_->port());
  const auto with_host = [&](std::string host, const std::string& at_port, const std::string& path) {
    host.append(":").append(at_port);
    return raw.Get(path.c_str(), httplib::Headers{{"Host", host}, {"Cookie", alice_->cookie()}});
  };
  for (const char* path : {"/api/session", "/"}) {
    EXPECT_EQ(with_host("attacker.example", port, path)->status, 403) << path;
    EXPECT_EQ(with_host("127.0.0.1", other_port, path)->status, 403) << "another port";
    EXPECT_EQ(with_host("10.1.2.3", port, path)->status, 403) << "an IP a loopback server is not";
  }
  for (const char* host : {"127.0.0.1", "localhost", "LOCALHOST", "[::1]", "lab.example.org"})
    EXPECT_EQ(with_host(host, port, "/api/session")->status, 200) << host;
}

TEST_F(WebSecurity, ARequestNamingItsHostTwiceIsRefused) {
  serve();
  httplib::Client raw("127.0.0.1", server_->port());
  const std::string mine = "127.0.0.1:" + std::to_string(server_->port());
  for (const char* second : {"attacker.example", "127.0.0.1"}) {
    const auto answer = raw.Get("/api/session", httplib::Headers{{"Host", mine}, {"Host", second}, {"Cookie", alice_->cookie()}});
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 400) << second;
  }
  EXPECT_EQ(raw.Get("/api/session", httplib::Headers{{"Host", mine}, {"Cookie", alice_->cookie()}})->status, 200);
}

TEST(HostCheck, ALoopbackServerAnswersItsNamesAndAnOpenServerAlsoAnyIpAndTheAllowedNames) {
  const web::HostCheck loopback("127.0.0.1", 8080, {});
  EXPECT_TRUE(loopback.allows("127.0.0.1:8080"));
  EXPECT_TRUE(loopback.allows("localhost:8080"));
  EXPECT_TRUE(loopback.allows("[::1]:8080"));
  EXPECT_FALSE(loopback.allows("localhost"));  // port 80
  EXPECT_FALSE(loopback.allows("evil.example:8080"));
  EXPECT_FALSE(loopback.allows("192.168.1.2:8080"));
  EXPECT_FALSE(loopback.allows(""));
  EXPECT_FALSE(loopback.allows("localhost:8080.evil.example"));
  const web::HostCheck open("0.0.0.0", 80, {"Lab.Example.org"});
  EXPECT_TRUE(open.allows("lab.example.org"));
  EXPECT_TRUE(open.allows("lab.example.org:80"));
  EXPECT_TRUE(open.allows("192.168.1.2"));
  EXPECT_TRUE(open.allows("[fe80::1]:80"));
  EXPECT_FALSE(open.allows("evil.example"));
  EXPECT_FALSE(open.allows("lab.example.org.evil.example"));
  EXPECT_NE(open.describe().find("lab.example.org"), std::string::npos);
}

TEST_F(WebSecurity, OneUsersRunsDoNotTakeEveryoneElsesExec) {
  serve();
  project_with_own_mission(*alice_, "alice", "mine");
  // A swarm large enough that four of its runs are still simulating when the fifth is asked for.
  const auto folder = projects_of("alice") / "mine";
  std::ifstream in(std::filesystem::path(::sd::test::source_dir()) / "missions" / "aggregation.json");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text = std::regex_replace(text, std::regex("\"robots\": 20"), "\"robots\": 1000");
  // 1000 robots for 999 ticks and the placement: exactly the 1,000,000 robot-frames Exec keeps.
  text = std::regex_replace(text, std::regex("\"duration\": 250"), "\"duration\": 99.9");
  text = std::regex_replace(text, std::regex("\"apothem\": 1.231, \"length\": 0.66"), "\"apothem\": 6, \"length\": 3.22");
  text = std::regex_replace(text, std::regex("\"radius\": 1.2\\}\\}"), "\"radius\": 5.5}}");
  std::ofstream(folder / "crowd.json") << text;
  const std::string crowd = (folder / "crowd.json").string();
  for (int i = 0; i < 4; ++i) {
    const Answer a = alice_->post("/api/runs", {{"text", kOneStateFsm}, {"mission", crowd}, {"seed", i + 1}});
    ASSERT_EQ(a.status, 200) << a.text;
  }
  const Answer fifth = alice_->post("/api/runs", {{"text", kOneStateFsm}, {"mission", crowd}, {"seed", 9}});
  EXPECT_EQ(fifth.status, 409) << fifth.text;
  EXPECT_NE(fifth.text.find("you are already simulating"), std::string::npos) << fifth.text;
  const Answer bobs = bob_->post("/api/runs", {{"text", kOneStateFsm}, {"mission", "aac"}, {"seed", 1}});
  EXPECT_EQ(bobs.status, 200) << "Bob's Exec must not wait for Alice's runs: " << bobs.text;
  // A run longer than Exec records is the CLI's.
  std::ofstream(folder / "endless.json") << std::regex_replace(text, std::regex("\"duration\": 99.9"), "\"duration\": 1000");
  const Answer too_long =
      alice_->post("/api/runs", {{"text", kOneStateFsm}, {"mission", (folder / "endless.json").string()}, {"seed", 1}});
  EXPECT_EQ(too_long.status, 400) << too_long.text;
  EXPECT_NE(too_long.text.find("robot-ticks"), std::string::npos) << too_long.text;
}

}  // namespace
}  // namespace sd::test
