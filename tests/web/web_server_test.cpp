// The web server as a browser meets it, over loopback HTTP against the real server in this
// process: every API route needs a session, every POST its CSRF token, users never reach each
// other's projects, designs or runs, bad input gets a clear error and the server goes on, an
// Exec scores exactly what `evaluate` scores, fifty viewers can watch one run, and a design
// started from the page can be followed, stopped and resumed.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <thread>
#include <vector>

#include "app/accounts.hpp"
#include "app/evaluation_job.hpp"
#include "app/experiment_job.hpp"
#include "app/experiment_report.hpp"
#include "app/pseudo_realities.hpp"
#include "reality/pseudo_reality.hpp"
#include "control/config_string.hpp"
#include "core/bounded_file.hpp"
#include "evaluation/simulation.hpp"
#include "export/argos_experiment.hpp"
#include "export/legacy_string.hpp"
#include "missions/catalogue.hpp"
#include "statistics/signed_rank.hpp"
#include "storage/design_store.hpp"
#include "storage/designs.hpp"
#include "storage/lease.hpp"
#include "storage/projects.hpp"
#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"
#include "test_paths.hpp"

namespace sd::test {
namespace {

using nlohmann::json;


class WebServer : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("sd-web-" + std::to_string(::getpid()) + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
    {
      app::Home home(root_ / "home");
      app::sign_up(home, "alice", "alice-password");
      app::sign_up(home, "bob", "bob-password");
    }
    server_.emplace(root_ / "home");
    alice_.emplace(server_->port());
    bob_.emplace(server_->port());
    ASSERT_TRUE(alice_->sign_in("alice", "alice-password"));
    ASSERT_TRUE(bob_->sign_in("bob", "bob-password"));
  }
  void TearDown() override {
    alice_.reset();
    bob_.reset();
    server_.reset();
    std::filesystem::remove_all(root_);
  }

  /// Alice's project on a 10-second AAC (a mission file of her own, put in the project's folder
  /// before the project is made, as a user of the server would) with a small budget.
  void alice_project(const std::string& name, const std::string& budget = "300") {
    const auto folder = root_ / "home" / "users" / "alice" / "projects" / name;
    std::filesystem::create_directories(folder);
    const auto mission = write_short_mission(folder);
    const Answer a = alice_->post("/api/projects", {{"name", name}, {"mission", mission.string()}, {"budget", budget}});
    ASSERT_EQ(a.status, 200) << a.text;
  }

  std::int64_t start_run(WebClient& client, const std::string& text, const std::string& mission, int seed) {
    const Answer a = client.post("/api/runs", {{"text", text}, {"mission", mission}, {"seed", seed}});
    EXPECT_EQ(a.status, 200) << a.text;
    return a.status == 200 ? a.body.at("id").get<std::int64_t>() : -1;
  }

  std::filesystem::path root_;
  std::optional<RunningServer> server_;
  std::optional<WebClient> alice_, bob_;
};

/// The data of the stream's events named `event`, in order.
std::vector<json> events(const std::string& stream, const std::string& event) {
  std::vector<json> out;
  const std::string head = "event: " + event + "\ndata: ";
  for (std::size_t at = stream.find(head); at != std::string::npos; at = stream.find(head, at + 1)) {
    const std::size_t start = at + head.size();
    out.push_back(json::parse(stream.substr(start, stream.find('\n', start) - start)));
  }
  return out;
}

TEST_F(WebServer, EveryApiRouteAnswers401WithoutASession) {
  WebClient stranger(server_->port());
  const std::vector<std::string> gets = {"/api/session", "/api/catalogue", "/api/missions", "/api/missions/svg?name=aac",
                                         "/api/runs/1/stream", "/api/projects", "/api/projects/p/status",
                                         "/api/projects/p/designs", "/api/projects/p/software",
                                         "/api/projects/p/status?design=1", "/api/projects/p/missions",
                                         "/api/projects/p/experiments", "/api/projects/p/experiments/e/report",
                                         "/api/projects/p/experiments/e/boxes.csv"};
  for (const auto& path : gets) {
    const Answer a = stranger.get(path);
    EXPECT_EQ(a.status, 401) << "GET " << path;
    EXPECT_TRUE(a.body.contains("error")) << a.text;
  }
  const std::vector<std::string> posts = {"/api/sign-out", "/api/parse", "/api/print", "/api/runs", "/api/projects",
                                          "/api/projects/p/designs", "/api/projects/p/designs/stop",
                                          "/api/projects/p/software", "/api/projects/p/delete",
                                          "/api/projects/p/designs/1/delete", "/api/projects/p/software/w/delete",
                                          "/api/projects/p/missions", "/api/projects/p/test"};
  for (const auto& path : posts) EXPECT_EQ(stranger.post(path, {{"text", kFsm}}).status, 401) << "POST " << path;
  // A forged or ended session is no session.
  httplib::Headers forged{{"Cookie", "sd_session=0123456789abcdef"}};
  EXPECT_EQ(stranger.raw().Get("/api/projects", forged)->status, 401);
  ASSERT_EQ(alice_->post("/api/sign-out", json::object()).status, 200);
  EXPECT_EQ(alice_->get("/api/projects").status, 401);
}

TEST_F(WebServer, TheSessionCookieIsHttpOnlyAndSameSiteStrict) {
  const auto result = alice_->raw().Post("/api/sign-in", R"({"name":"alice","password":"alice-password"})", "application/json");
  ASSERT_EQ(result->status, 200);
  const std::string cookie = result->get_header_value("Set-Cookie");
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos) << cookie;
  EXPECT_NE(cookie.find("SameSite=Strict"), std::string::npos) << cookie;
  EXPECT_EQ(alice_->raw().Post("/api/sign-in", R"({"name":"alice","password":"wrong-password"})", "application/json")->status,
            401);
  const auto unknown = alice_->raw().Post("/api/sign-in", R"({"name":"carol","password":"wrong-password"})", "application/json");
  EXPECT_EQ(unknown->status, 401);
  EXPECT_EQ(unknown->body.find("carol"), std::string::npos) << "the answer must not tell which names exist";
  // Served directly over HTTP, a Secure cookie would never come back: not Secure.
  EXPECT_EQ(cookie.find("Secure"), std::string::npos) << cookie;
}

TEST_F(WebServer, BehindATlsProxyTheSessionCookieIsSecureAndStillWorks) {
  RunningServer proxied(web::WebServerOptions{"127.0.0.1", 0, {}, root_ / "home", {}, {}, true});
  WebClient carol(proxied.port());
  const auto result = carol.raw().Post("/api/sign-in", R"({"name":"alice","password":"alice-password"})", "application/json");
  ASSERT_EQ(result->status, 200);
  const std::string cookie = result->get_header_value("Set-Cookie");
  EXPECT_NE(cookie.find("; Secure"), std::string::npos) << cookie;
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos) << cookie;
  // The proxy forwards the cookie it got over HTTPS: the session works as ever.
  WebClient alice(proxied.port());
  ASSERT_TRUE(alice.sign_in("alice", "alice-password"));
  EXPECT_EQ(alice.get("/api/projects").status, 200);
  const Answer out = alice.post("/api/sign-out", json::object());
  EXPECT_EQ(out.status, 200);
  bool cleared_secure = false;
  for (const auto& [name, value] : out.headers)
    if (name == "Set-Cookie") cleared_secure = value.find("Max-Age=0") != std::string::npos && value.find("; Secure") != std::string::npos;
  EXPECT_TRUE(cleared_secure);
}

TEST_F(WebServer, BehindATlsProxyFailedSignInsLockTheForwardedClientNotEveryone) {
  RunningServer proxied(web::WebServerOptions{"127.0.0.1", 0, {}, root_ / "home", {}, {}, true});
  WebClient client(proxied.port());
  const auto sign_in = [&](const std::string& forwarded_for, const std::string& name, const std::string& password) {
    const httplib::Headers headers{{"X-Forwarded-For", forwarded_for}};
    return client.raw()
        .Post("/api/sign-in", headers, json{{"name", name}, {"password", password}}.dump(), "application/json")
        ->status;
  };
  // Twenty failures from one client (each under another name, so that no name locks)...
  for (int i = 0; i < 20; ++i) EXPECT_EQ(sign_in("198.51.100.7, 203.0.113.5", "nobody" + std::to_string(i), "x-wrong-pass"), 401);
  // ...lock that client, named by the address the proxy appended, whatever comes before it...
  EXPECT_EQ(sign_in("203.0.113.5", "alice", "alice-password"), 429);
  EXPECT_EQ(sign_in("10.9.9.9, 203.0.113.5", "alice", "alice-password"), 429);
  // ...and no one else behind the same proxy.
  EXPECT_EQ(sign_in("203.0.113.9", "alice", "alice-password"), 200);
  EXPECT_EQ(sign_in("203.0.113.5, 203.0.113.10", "bob", "bob-password"), 200);

  // Without --behind-tls the header is anyone's to write: it names no one.
  WebClient direct(server_->port());
  for (int i = 0; i < 20; ++i) {
    const httplib::Headers spoofed{{"X-Forwarded-For", "192.0.2." + std::to_string(i)}};
    direct.raw().Post("/api/sign-in", spoofed, json{{"name", "nobody" + std::to_string(i)}, {"password", "x-wrong-pass"}}.dump(),
                      "application/json");
  }
  const httplib::Headers fresh{{"X-Forwarded-For", "192.0.2.200"}};
  EXPECT_EQ(direct.raw().Post("/api/sign-in", fresh, R"({"name":"alice","password":"alice-password"})", "application/json")->status,
            429);
}

TEST_F(WebServer, APostWithoutTheCsrfTokenIsRefused) {
  const Answer without = alice_->post("/api/parse", {{"text", kFsm}}, false);
  EXPECT_EQ(without.status, 403);
  EXPECT_NE(without.body.at("error").get<std::string>().find("X-CSRF-Token"), std::string::npos);
  // Bob's token is not Alice's.
  httplib::Headers mixed{{"Cookie", alice_->cookie()}, {"X-CSRF-Token", "0"}};
  EXPECT_EQ(alice_->raw().Post("/api/parse", mixed, json{{"text", kFsm}}.dump(), "application/json")->status, 403);
  // A form post (not JSON) is refused whatever it carries.
  EXPECT_EQ(alice_->raw().Post("/api/sign-in", "name=alice&password=alice-password", "application/x-www-form-urlencoded")->status,
            415);
  EXPECT_EQ(alice_->post("/api/parse", {{"text", kFsm}}).status, 200);
  // A page of another site cannot make Alice's browser delete her project.
  alice_project("mine");
  EXPECT_EQ(alice_->post("/api/projects/mine/delete", {{"confirm", "mine"}}, false).status, 403);
  EXPECT_EQ(alice_->get("/api/projects").body.size(), 1u);
}

TEST_F(WebServer, ASecondUserCanNeitherListNorWatchNorStopTheFirstUsersWork) {
  alice_project("mine");
  const std::int64_t run = start_run(*alice_, kFsm, "aac", 3);
  ASSERT_EQ(alice_->post("/api/projects/mine/software", {{"name", "walker"}, {"text", kFsm}}).status, 200);

  EXPECT_TRUE(bob_->get("/api/projects").body.empty());
  EXPECT_EQ(bob_->get("/api/projects/mine/status").status, 404);
  EXPECT_EQ(bob_->get("/api/projects/mine/designs").status, 404);
  EXPECT_EQ(bob_->get("/api/projects/mine/software").status, 404);
  EXPECT_EQ(bob_->post("/api/projects/mine/designs", json::object()).status, 404);
  EXPECT_EQ(bob_->post("/api/projects/mine/designs/stop", json::object()).status, 404);
  EXPECT_EQ(bob_->stream("/api/runs/" + std::to_string(run) + "/stream").status, 404);
  // Alice's mission file is hers: Bob cannot run or draw it by path.
  const std::string file = alice_->get("/api/projects").body.at(0).at("mission");
  EXPECT_EQ(bob_->get("/api/missions/svg?name=" + file).status, 404);
  EXPECT_EQ(bob_->post("/api/runs", {{"text", kFsm}, {"mission", file}, {"seed", 1}}).status, 404);
  for (const json& m : bob_->get("/api/missions").body) EXPECT_NE(m.at("name"), file);

  // Alice has all of it.
  ASSERT_EQ(alice_->get("/api/projects").body.size(), 1u);
  EXPECT_EQ(alice_->stream("/api/runs/" + std::to_string(run) + "/stream").status, 200);
  EXPECT_EQ(alice_->get("/api/projects/mine/software").body.at(0).at("name"), "walker");
  bool listed = false;
  for (const json& m : alice_->get("/api/missions").body) listed = listed || m.at("name") == file;
  EXPECT_TRUE(listed);
}

/// The catalogue's AAC as a user's own mission document named `name`, shortened to 10 s.
json own_mission(const std::string& name) {
  json doc = json::parse(load_mission("aac").document, nullptr, true, /*ignore_comments=*/true);
  doc["name"] = name;
  doc["duration"] = 10;
  doc.erase("argos");
  return doc;
}

TEST_F(WebServer, AMissionUploadedIntoAProjectIsStoredPrivatelyListedAndRunnableByItsOwnerOnly) {
  alice_project("mine");
  const std::string text = own_mission("corner").dump(1);
  const Answer up = alice_->post("/api/projects/mine/missions", {{"name", "corner"}, {"text", text}});
  ASSERT_EQ(up.status, 200) << up.text;
  const std::string file = up.body.at("name");
  EXPECT_EQ(up.body.at("robots"), 20);
  // Stored as sent, in the project's folder, readable by its owner only.
  const auto stored = root_ / "home" / "users" / "alice" / "projects" / "mine" / "missions" / "corner.json";
  EXPECT_TRUE(std::filesystem::equivalent(file, stored));
  std::ifstream in(stored);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), text);
  EXPECT_EQ(std::filesystem::status(stored).permissions() & std::filesystem::perms::all,
            std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);

  const Answer listed = alice_->get("/api/projects/mine/missions");
  ASSERT_EQ(listed.body.size(), 1u);
  EXPECT_EQ(listed.body.at(0).at("name"), "corner");
  bool offered = false;
  for (const json& m : alice_->get("/api/missions").body) offered = offered || m.at("name") == file;
  EXPECT_TRUE(offered);
  EXPECT_EQ(alice_->get("/api/missions/svg?name=" + file).status, 200);
  start_run(*alice_, kFsm, file, 2);
  // A new project designs on it.
  EXPECT_EQ(alice_->post("/api/projects", {{"name", "own"}, {"mission", file}, {"budget", "300"}}).status, 200);

  // Bob neither sees, reads, runs nor writes any of it.
  EXPECT_EQ(bob_->get("/api/projects/mine/missions").status, 404);
  EXPECT_EQ(bob_->post("/api/projects/mine/missions", {{"name", "corner"}, {"text", own_mission("x").dump()}}).status, 404);
  EXPECT_EQ(bob_->get("/api/missions/svg?name=" + file).status, 404);
  EXPECT_EQ(bob_->post("/api/runs", {{"text", kFsm}, {"mission", file}, {"seed", 1}}).status, 404);
  for (const json& m : bob_->get("/api/missions").body) EXPECT_NE(m.at("name"), file);
  EXPECT_EQ(bob_->get("/api/missions/text?name=" + file).status, 404);
  EXPECT_EQ(bob_->post("/api/projects/mine/missions/preview", {{"name", "corner"}, {"text", text}}).status, 404);

  // The mission editor's reads: a mission's text as written, and a drawing of a draft stored nowhere.
  EXPECT_EQ(alice_->get("/api/missions/text?name=" + file).body.at("text"), text);
  EXPECT_EQ(alice_->get("/api/missions/text?name=aac").body.at("text"), load_mission("aac").document);
  const Answer drawn = alice_->post("/api/projects/mine/missions/preview", {{"name", "draft"}, {"text", own_mission("draft").dump()}});
  ASSERT_EQ(drawn.status, 200) << drawn.text;
  EXPECT_EQ(drawn.body.at("svg").get<std::string>().rfind("<svg", 0), 0u);
  EXPECT_EQ(drawn.body.at("mission").at("robots"), 20);
  EXPECT_FALSE(std::filesystem::exists(stored.parent_path() / "draft.json"));
  json crowded = own_mission("crowded");
  crowded["arena"]["walls"].push_back({{"box", {{"center", {0, 0}}, {"size", {2.4, 2.4}}}}});
  const Answer refused = alice_->post("/api/projects/mine/missions/preview", {{"name", "crowded"}, {"text", crowded.dump()}});
  EXPECT_EQ(refused.status, 400);
  EXPECT_NE(refused.text.find("cannot place robot"), std::string::npos) << refused.text;
  std::ifstream again(stored);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), text);
}

TEST_F(WebServer, ABadMissionUploadGetsOneLineNamingTheProblemAndStoresNothing) {
  alice_project("mine");
  json blocked = own_mission("blocked");  // a wall over nearly all of the start disc
  blocked["arena"]["walls"].push_back({{"box", {{"center", {0, 0}}, {"size", {2.4, 2.4}}}}});
  json bad_field = own_mission("bad");
  bad_field["robots"] = 0;
  const std::vector<std::pair<json, std::string>> cases{
      {{{"name", "broken"}, {"text", "{\"name\": \"broken\","}}, "not valid JSON"},
      {{{"name", "bad"}, {"text", bad_field.dump()}}, "robots"},
      {{{"name", "blocked"}, {"text", blocked.dump()}}, "cannot place robot"},
      {{{"name", "../escape"}, {"text", own_mission("x").dump()}}, "mission name"},
      {{{"name", ".hidden"}, {"text", own_mission("x").dump()}}, "mission name"},
  };
  for (const auto& [body, words] : cases) {
    const Answer a = alice_->post("/api/projects/mine/missions", body);
    EXPECT_EQ(a.status, 400) << body.at("name");
    const std::string error = a.body.is_object() ? a.body.value("error", "") : "";
    EXPECT_NE(error.find(words), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  // A file over 1 MiB cannot even be sent: the request is refused before it is read.
  const Answer huge =
      alice_->post("/api/projects/mine/missions", {{"name", "huge"}, {"text", std::string(kMaxInputFileBytes, ' ')}});
  EXPECT_EQ(huge.status, 413);
  ASSERT_TRUE(huge.body.is_object()) << huge.text;
  EXPECT_NE(huge.body.value("error", "").find("1 MiB"), std::string::npos) << huge.text;
  const auto folder = root_ / "home" / "users" / "alice" / "projects" / "mine" / "missions";
  EXPECT_TRUE(!std::filesystem::exists(folder) || std::filesystem::is_empty(folder));
  EXPECT_TRUE(alice_->get("/api/projects/mine/missions").body.empty());
}

TEST_F(WebServer, AnExperimentsReportIsServedToItsOwnerOnlyAsOneSelfContainedPage) {
  alice_project("mine");
  {
    // A one-design experiment on the project's 10-second mission, run by the application layer.
    experiments::Protocol protocol;
    protocol.name = "tiny";
    protocol.designs = 1;
    protocol.assessment_seeds = 2;
    protocol.missions = {{alice_->get("/api/projects").body.at(0).at("mission"), 1008,
                          {{"alone", "automode", {"fsm"}, {"chocolate"}}}}};
    app::Home home(root_ / "home");
    const storage::User alice = app::sign_in_here(home, "alice", "alice-password").user;
    app::StartedExperiment e = app::start_experiment(home, alice, app::plan_experiment(protocol), {"mine", storage::owner_text(storage::server_thread("test"))});
    app::run_experiment(e, {.threads = 2, .evaluator = nullptr, .observer = nullptr, .cancel = nullptr});
  }
  const Answer list = alice_->get("/api/projects/mine/experiments");
  ASSERT_EQ(list.status, 200) << list.text;
  ASSERT_EQ(list.body.size(), 1u);
  EXPECT_EQ(list.body[0].at("name"), "tiny");
  EXPECT_EQ(list.body[0].at("designs_done"), 1);
  EXPECT_EQ(alice_->get("/api/projects/mine/status").body.at("experiments"), list.body);

  // The page needs the front end's report bundle: a server with the built web root.
  RunningServer with_pages(root_ / "home", std::filesystem::path(::sd::test::swarmdesign_binary()).parent_path() / "web-root");
  WebClient alice(with_pages.port()), bob(with_pages.port());
  ASSERT_TRUE(alice.sign_in("alice", "alice-password"));
  ASSERT_TRUE(bob.sign_in("bob", "bob-password"));
  const Answer page = alice.get("/api/projects/mine/experiments/tiny/report");
  ASSERT_EQ(page.status, 200) << page.text.substr(0, 300);
  EXPECT_NE(page.text.find("<script id=\"report-data\" type=\"application/json\">"), std::string::npos);
  std::vector<std::string> policies;
  for (const auto& [name, value] : page.headers)
    if (name == "Content-Security-Policy") policies.push_back(value);
  ASSERT_EQ(policies.size(), 1u) << "two policies would both apply";
  EXPECT_NE(policies[0].find("default-src 'none'"), std::string::npos) << policies[0];
  EXPECT_NE(policies[0].find("script-src 'unsafe-inline'"), std::string::npos) << policies[0];

  // The data files the page points to, relative to its address: byte for byte what
  // `swarmdesign report` writes next to report.html.
  std::vector<std::filesystem::path> written;
  {
    app::Home home(root_ / "home");
    const storage::User owner = app::sign_in_here(home, "alice", "alice-password").user;
    written = app::write_experiment_report(app::experiment_report_document(home, owner, "tiny", "mine"), root_ / "report",
                                           std::filesystem::path(::sd::test::swarmdesign_binary()).parent_path() / "web-root");
  }
  int served = 0;
  for (const auto& file : written) {
    const std::string name = file.filename().string();
    if (name == "report.html") continue;
    const Answer data = alice.get("/api/projects/mine/experiments/tiny/" + name);
    ASSERT_EQ(data.status, 200) << name;
    std::ifstream in(file, std::ios::binary);
    const std::string on_disk(std::istreambuf_iterator<char>(in), {});
    if (name == "report.json") {
      // Two documents built apart in time differ in their stamp only.
      auto stamp_free = [](const std::string& text) {
        json document = json::parse(text);
        document.at("experiment").erase("generated_at");
        return document;
      };
      EXPECT_EQ(stamp_free(data.text), stamp_free(on_disk));
    } else {
      EXPECT_EQ(data.text, on_disk) << name;
    }
    EXPECT_EQ(bob.get("/api/projects/mine/experiments/tiny/" + name).status, 404) << name;
    ++served;
  }
  EXPECT_EQ(served, 10);  // report.json and nine tables
  EXPECT_EQ(alice.get("/api/projects/mine/experiments/tiny/secrets.csv").status, 404);
  EXPECT_EQ(alice.get("/api/projects/mine/experiments/tiny/..%2F..%2Fswarmdesign.db").status, 404);
  EXPECT_EQ(WebClient(with_pages.port()).get("/api/projects/mine/experiments/tiny/boxes.csv").status, 401);

  EXPECT_EQ(alice.get("/api/projects/mine/experiments/other/report").status, 404);
  EXPECT_EQ(bob.get("/api/projects/mine/experiments").status, 404);
  EXPECT_EQ(bob.get("/api/projects/mine/experiments/tiny/report").status, 404);
  EXPECT_EQ(WebClient(with_pages.port()).get("/api/projects/mine/experiments/tiny/report").status, 401);
}

TEST_F(WebServer, BadInputGetsAClearErrorAndTheServerGoesOn) {
  const Answer bad = alice_->post("/api/parse", {{"text", "--fsm-config --nstates 1 --s0 0 --rwmX 5"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(bad.body.at("token"), "--rwmX");
  EXPECT_NE(bad.body.at("error").get<std::string>().find("--rwmX"), std::string::npos);

  EXPECT_EQ(alice_->post("/api/runs", {{"text", "--fsm-config --nstates 9"}, {"mission", "aac"}, {"seed", 1}}).status, 400);
  EXPECT_EQ(alice_->post("/api/runs", {{"text", kFsm}, {"mission", "no-such-mission"}, {"seed", 1}}).status, 400);
  EXPECT_EQ(alice_->post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", "three"}}).status, 400);
  EXPECT_EQ(alice_->post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", -4}}).status, 400);
  EXPECT_EQ(alice_->post("/api/runs", {{"text", kFsm}, {"mission", "/etc/passwd"}, {"seed", 1}}).status, 404);
  // A malformed mission file of her own project is refused when the project is made.
  const auto own = root_ / "home" / "users" / "alice" / "projects" / "p";
  std::filesystem::create_directories(own);
  std::ofstream(own / "broken.json") << R"({"name": "broken", "duration": -3})";
  const Answer broken = alice_->post("/api/projects", {{"name", "p"}, {"mission", (own / "broken.json").string()}, {"budget", "300"}});
  EXPECT_EQ(broken.status, 400) << broken.text;
  EXPECT_TRUE(alice_->get("/api/projects").body.empty()) << "a refused project must leave nothing behind";
  std::filesystem::remove_all(own);
  EXPECT_EQ(alice_->post("/api/projects", {{"name", "p"}, {"mission", "aac"}, {"budget", "ten"}}).status, 400);
  EXPECT_EQ(alice_->post("/api/print", {{"software", {{"architecture", "fsm"}, {"states", json::array()}}}}).status, 400);
  EXPECT_EQ(alice_->post("/api/print", {{"software", {{"architecture", "fsm"},
                                                       {"states", {{{"behaviour", {{"id", 99}}}}}}}}}).status,
            400);

  // Not JSON, and too large.
  httplib::Headers h{{"Cookie", alice_->cookie()}, {"X-CSRF-Token", alice_->get("/api/session").body.at("csrf")}};
  EXPECT_EQ(alice_->raw().Post("/api/parse", h, "{not json", "application/json")->status, 400);
  const auto huge = alice_->raw().Post("/api/parse", h, std::string(2 << 20, ' '), "application/json");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->status, 413);

  // Still serving.
  EXPECT_EQ(alice_->get("/api/session").status, 200);
  EXPECT_EQ(alice_->post("/api/parse", {{"text", kFsm}}).status, 200);
}

TEST_F(WebServer, ParseAndPrintGoBothWaysThroughTheOneParser) {
  const Answer parsed = alice_->post("/api/parse", {{"text", kFsm}});
  ASSERT_EQ(parsed.status, 200);
  json model = parsed.body.at("software");
  EXPECT_EQ(model.at("states").size(), 2u);
  EXPECT_EQ(parsed.body.at("text"), to_config_string(parse_control_software(kFsm)));
  model["states"][0]["behaviour"]["parameters"]["rwm"] = 7;
  const Answer printed = alice_->post("/api/print", {{"software", model}});
  ASSERT_EQ(printed.status, 200) << printed.text;
  EXPECT_NE(printed.body.at("text").get<std::string>().find("--rwm0 7"), std::string::npos);

  const json catalogue = alice_->get("/api/catalogue").body;
  EXPECT_EQ(catalogue.at("flavours").size(), 5u);
  std::size_t behaviours = 0;
  for (ModuleKind kind : {ModuleKind::Behaviour}) behaviours += modules(kind).size();
  EXPECT_EQ(catalogue.at("behaviours").size(), behaviours);
}

TEST_F(WebServer, AnExecStreamsTheWholeRunAndScoresExactlyWhatEvaluateScores) {
  const std::int64_t run = start_run(*alice_, kFsm, "aac", 3);
  const Answer stream = alice_->stream("/api/runs/" + std::to_string(run) + "/stream");
  ASSERT_EQ(stream.status, 200);
  const auto scene = events(stream.text, "scene");
  ASSERT_EQ(scene.size(), 1u);
  EXPECT_EQ(scene[0].at("robots"), 20);
  EXPECT_NE(scene[0].at("svg").get<std::string>().find("<svg"), std::string::npos);

  const auto frames = events(stream.text, "frames");
  int ticks = 0;
  for (const json& f : frames) {
    EXPECT_EQ(f.at("first"), ticks);
    ticks += f.at("count").get<int>();
    EXPECT_EQ(f.at("x").size(), 20u * f.at("count").get<std::size_t>());
  }
  EXPECT_EQ(ticks, 1201);  // placement and 1200 ticks
  EXPECT_NE(frames.front().at("x").at(0), frames.back().at("x").at(0)) << "the robots moved";

  const auto end = events(stream.text, "end");
  ASSERT_EQ(end.size(), 1u);
  const double streamed = end[0].at("score").get<double>();
  const Mission mission = load_mission("aac");
  const ControlSoftware software = parse_control_software(kFsm);
  const double evaluated = app::score_seeds(mission, software, {3}).at(0);
  EXPECT_EQ(std::memcmp(&streamed, &evaluated, sizeof(double)), 0) << streamed << " vs " << evaluated;
}

TEST_F(WebServer, FiftyViewersWatchOneRunAndEachGetsAllOfIt) {
  const std::int64_t run = start_run(*alice_, kFsm, "aac", 5);
  const std::string path = "/api/runs/" + std::to_string(run) + "/stream";
  std::vector<std::string> seen(50);
  std::vector<std::thread> viewers;
  for (std::size_t v = 0; v < seen.size(); ++v)
    viewers.emplace_back([&, v] {
      WebClient viewer(server_->port(), *alice_);  // fifty tabs of Alice's browser
      const Answer a = viewer.stream(path);
      seen[v] = a.status == 200 ? a.text : std::to_string(a.status) + " " + a.text;
    });
  for (auto& t : viewers) t.join();
  const auto reference = events(seen[0], "end");
  ASSERT_EQ(reference.size(), 1u);
  for (std::size_t v = 0; v < seen.size(); ++v) {
    EXPECT_EQ(events(seen[v], "frames").size(), events(seen[0], "frames").size()) << "viewer " << v << ": " << seen[v].substr(0, 200);
    EXPECT_EQ(events(seen[v], "end"), reference) << "viewer " << v;
  }
  EXPECT_EQ(alice_->get("/api/session").status, 200);
}

// A browser keeps its connection open between requests (keep-alive), and cpp-httplib serves a
// connection on one thread for its whole life: with fewer threads than open connections, the
// next tab waited until another's connection went idle for the keep-alive timeout (5 s), or for
// ever behind tabs that poll (bench/load_bench found it with 200 tabs). Two hundred open
// connections and one more tab: it is answered at once, well inside those 5 s.
TEST_F(WebServer, TwoHundredBrowsersKeepingTheirConnectionsOpenDoNotLockOutTheNext) {
  std::vector<std::unique_ptr<httplib::Client>> tabs;
  const httplib::Headers session{{"Cookie", alice_->cookie()}};
  for (int i = 0; i < 200; ++i) {
    tabs.push_back(std::make_unique<httplib::Client>("127.0.0.1", server_->port()));
    tabs.back()->set_keep_alive(true);
    tabs.back()->set_read_timeout(std::chrono::seconds(3));  // below the keep-alive timeout
    const auto r = tabs.back()->Get("/api/session", session);
    ASSERT_TRUE(r) << "tab " << i << ": " << httplib::to_string(r.error());
    ASSERT_EQ(r->status, 200) << "tab " << i;
  }
  httplib::Client next("127.0.0.1", server_->port());
  next.set_read_timeout(std::chrono::seconds(3));
  const auto r = next.Get("/api/session", session);
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 200);
}

// A hundred tabs opening their connections in the same instant: the kernel completes each
// connection only while the server's queue of connections not yet accepted has room, and drops
// the rest for TCP to send again a second later (or to fail). With cpp-httplib's backlog of 5
// that queue overflowed; the server now listens with the system's maximum, and every one is
// connected long before TCP's first retry.
TEST_F(WebServer, AHundredConnectionsOpenedAtOnceAreAllAccepted) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(server_->port()));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::vector<pollfd> sockets;
  for (int i = 0; i < 100; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    ASSERT_GE(fd, 0);
    const int r = ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    ASSERT_TRUE(r == 0 || errno == EINPROGRESS) << std::strerror(errno);
    sockets.push_back({fd, POLLOUT, 0});
  }
  // Connected when writable; TCP's first retry of a dropped opening comes after 1 s.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(900);
  std::size_t connected = 0;
  while (connected < sockets.size() && std::chrono::steady_clock::now() < deadline) {
    ::poll(sockets.data(), sockets.size(), 50);
    connected = 0;
    for (pollfd& p : sockets) {
      if (p.revents & POLLOUT) p.events = 0;  // connected: poll it no more
      connected += p.events == 0 ? 1 : 0;
    }
  }
  for (const pollfd& p : sockets) ::close(p.fd);
  EXPECT_EQ(connected, sockets.size());
  EXPECT_EQ(alice_->get("/api/session").status, 200);
}

// Sign-ins wait for one of the server's few password-check slots (web/password_slots.hpp, which
// bounds Argon2id's memory): twenty-four at once, right and wrong, each still gets its answer.
TEST_F(WebServer, TwentyFourSignInsAtOnceEachGetTheirAnswer) {
  std::vector<int> status(24);
  std::vector<std::thread> tabs;
  for (std::size_t i = 0; i < status.size(); ++i)
    tabs.emplace_back([&, i] {
      httplib::Client tab("127.0.0.1", server_->port());
      tab.set_read_timeout(std::chrono::seconds(60));
      const std::string password = i % 6 == 5 ? "not-alice-password" : "alice-password";
      const auto r = tab.Post("/api/sign-in", json{{"name", "alice"}, {"password", password}}.dump(), "application/json");
      status[i] = r ? r->status : -100 - static_cast<int>(r.error());  // httplib::Error, for the message
    });
  for (auto& t : tabs) t.join();
  for (std::size_t i = 0; i < status.size(); ++i) EXPECT_EQ(status[i], i % 6 == 5 ? 401 : 200) << "sign-in " << i;
}

// The page stops a design whoever runs it, through the design's backend: here a CLI process of
// this machine (a stand-in that only sleeps, leased as a CLI owner), which gets SIGTERM; a
// design on a thread of another server is still refused, and another user never reaches it.
TEST_F(WebServer, ThePageStopsADesignTheCliRunsButNotAnotherServersThread) {
  alice_project("c");
  const pid_t cli = ::fork();
  ASSERT_GE(cli, 0);
  if (cli == 0) {
    ::execl("/bin/sleep", "sleep", "600", static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  std::int64_t design_id = 0;
  {
    app::Home home(root_ / "home");
    const storage::User alice = app::sign_in_here(home, "alice", "alice-password").user;
    storage::Designs designs(home.workspace(), storage::Projects(home.workspace(), alice).get("c"));
    design_id = designs.start({"fsm", "chocolate", 1, storage::owner_text(storage::local_process(cli))}).id;
  }
  EXPECT_EQ(alice_->get("/api/projects/c/status").body.at("design").at("state"), "running");
  EXPECT_EQ(bob_->post("/api/projects/c/designs/stop", json::object()).status, 404);
  const Answer stop = alice_->post("/api/projects/c/designs/stop", json::object());
  ASSERT_EQ(stop.status, 200) << stop.text;
  EXPECT_EQ(stop.body, (json{{"stopping", true}}));
  int wait_status = 0;
  ASSERT_EQ(::waitpid(cli, &wait_status, 0), cli);
  EXPECT_TRUE(WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGTERM);
  const Answer after = alice_->get("/api/projects/c/status");
  EXPECT_EQ(after.body.at("design").at("id"), design_id);
  EXPECT_EQ(after.body.at("design").at("state"), "interrupted");

  {  // A thread of another server (this process's pid, another job name): only that server stops it.
    app::Home home(root_ / "home");
    const storage::User alice = app::sign_in_here(home, "alice", "alice-password").user;
    storage::Designs designs(home.workspace(), storage::Projects(home.workspace(), alice).get("c"));
    designs.abandon(design_id);
    designs.start({"fsm", "chocolate", 2, storage::owner_text(storage::server_thread("other-server-1"))});
  }
  const Answer refused = alice_->post("/api/projects/c/designs/stop", json::object());
  EXPECT_EQ(refused.status, 409) << refused.text;
  EXPECT_EQ(alice_->get("/api/projects/c/status").body.at("design").at("state"), "running");
}

TEST_F(WebServer, ADesignStartedFromThePageIsFollowedStoppedAndResumed) {
  alice_project("d", "1100");
  const Answer started = alice_->post("/api/projects/d/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 7}});
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body.at("state"), "running");
  const Answer second = alice_->post("/api/projects/d/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"}});
  EXPECT_EQ(second.status, 409) << "one design at a time: " << second.text;

  std::int64_t used = 0;
  ASSERT_TRUE(wait_until([&] {
    const Answer s = alice_->get("/api/projects/d/status");
    used = s.body.at("progress").at("experiments_used").get<std::int64_t>();
    return s.body.at("running_here").get<bool>() && used > 0;
  }, std::chrono::seconds(120)));
  ASSERT_EQ(alice_->post("/api/projects/d/designs/stop", json::object()).status, 200);
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/d/status").body.at("design").at("state") != "running"; },
                         std::chrono::seconds(120)));
  const Answer stopped = alice_->get("/api/projects/d/status");
  EXPECT_EQ(stopped.body.at("design").at("state"), "interrupted");
  EXPECT_FALSE(stopped.body.at("running_here").get<bool>());

  const Answer resumed = alice_->post("/api/projects/d/designs", json::object());
  ASSERT_EQ(resumed.status, 200) << resumed.text;
  EXPECT_EQ(resumed.body.at("id"), started.body.at("id")) << "the interrupted design resumes";
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/d/status").body.at("design").at("state") == "finished"; },
                         std::chrono::seconds(300)));
  const Answer done = alice_->get("/api/projects/d/status");
  EXPECT_GE(done.body.at("progress").at("experiments_used").get<std::int64_t>(), used);
  EXPECT_FALSE(done.body.at("race_log").empty());
  EXPECT_EQ(alice_->get("/api/projects/d/designs").body.size(), 1u);
  // The page's poll: the same without the race log, whose counts its progress holds.
  const Answer polled = alice_->get("/api/projects/d/status?race_log=false");
  ASSERT_EQ(polled.status, 200) << polled.text;
  EXPECT_FALSE(polled.body.contains("race_log"));
  EXPECT_EQ(polled.body.at("convergence"), done.body.at("convergence"));
  EXPECT_EQ(polled.body.at("progress"), done.body.at("progress"));
  const json& last_race = done.body.at("race_log").back().at("configurations");
  EXPECT_EQ(polled.body.at("progress").at("race_alive"),
            std::count_if(last_race.begin(), last_race.end(), [](const json& c) { return c.at("eliminated_after").is_null(); }));
  const Answer wrong = alice_->get("/api/projects/d/status?race_log=maybe");
  EXPECT_EQ(wrong.status, 400);
  EXPECT_EQ(wrong.body.at("error"), "race_log must be true or false, not 'maybe'");

  // Its best tested on fresh seeds from the page scores what test-design scores.
  const Answer tested = alice_->post("/api/projects/d/test", {{"seeds", "11-15"}});
  ASSERT_EQ(tested.status, 200) << tested.text;
  EXPECT_EQ(tested.body.at("design"), started.body.at("id"));
  const std::string best = tested.body.at("control_software");
  const std::string mission = alice_->get("/api/projects").body.at(0).at("mission");
  const std::vector<double> expected =
      app::score_seeds(load_mission(mission), parse_control_software(best), {11, 12, 13, 14, 15});
  ASSERT_EQ(tested.body.at("runs").size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(tested.body.at("runs").at(i).at("score").get<double>(), expected[i]);
  EXPECT_TRUE(tested.body.contains("sd") && tested.body.contains("mean") && tested.body.contains("median"));
  EXPECT_EQ(alice_->post("/api/projects/d/test", {{"seeds", "1-500"}}).status, 400);
  EXPECT_EQ(alice_->post("/api/projects/d/test", {{"seeds", "1-5"}, {"design", 99}}).status, 404);
  EXPECT_EQ(bob_->post("/api/projects/d/test", {{"seeds", "1-5"}}).status, 404);
  // Control software sent with the request is tested instead (the page sends the best it shows).
  const Answer given = alice_->post("/api/projects/d/test", {{"seeds", "11-15"}, {"text", best}});
  ASSERT_EQ(given.status, 200) << given.text;
  EXPECT_EQ(given.body.at("runs"), tested.body.at("runs"));
  EXPECT_EQ(alice_->post("/api/projects/d/test", {{"seeds", "1-2"}, {"text", "--fsm-config --nstates 1 --s0 99"}}).status, 400);
}

TEST_F(WebServer, EarlierDesignsOpenAndWhatIsDeletedIsOnlyWhatWasNamedAndOnlyByItsOwner) {
  const json fsm{{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 3}};
  alice_project("d", "200000");
  alice_project("kept", "200000");
  ASSERT_EQ(alice_->post("/api/projects/d/software", {{"name", "walker"}, {"text", kFsm}}).status, 200);
  ASSERT_EQ(alice_->post("/api/projects/d/software", {{"name", "other"}, {"text", kFsm}}).status, 200);
  const Answer first = alice_->post("/api/projects/d/designs", fsm);
  ASSERT_EQ(first.status, 200) << first.text;
  const std::string id = std::to_string(first.body.at("id").get<std::int64_t>());
  const auto folder = root_ / "home" / "users" / "alice" / "projects" / "d" / "designs" / id;
  ASSERT_TRUE(std::filesystem::is_directory(folder));

  // Nothing of a running design goes, nor the project holding it.
  EXPECT_EQ(alice_->post("/api/projects/d/designs/" + id + "/delete", json::object()).status, 409);
  EXPECT_EQ(alice_->post("/api/projects/d/delete", {{"confirm", "d"}}).status, 409);
  ASSERT_EQ(alice_->post("/api/projects/d/designs/stop", json::object()).status, 200);
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/d/status").body.at("design").at("state") != "running"; },
                         std::chrono::seconds(120)));
  const Answer second = alice_->post("/api/projects/d/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"},
                                                                 {"seed", 4}, {"fresh", true}});
  ASSERT_EQ(second.status, 200) << second.text;
  ASSERT_EQ(alice_->post("/api/projects/d/designs/stop", json::object()).status, 200);
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/d/status").body.at("design").at("state") != "running"; },
                         std::chrono::seconds(120)));

  // The earlier design opens by its number, as status --design shows it.
  const Answer earlier = alice_->get("/api/projects/d/status?design=" + id);
  ASSERT_EQ(earlier.status, 200) << earlier.text;
  EXPECT_EQ(earlier.body.at("design").at("id"), first.body.at("id"));
  EXPECT_EQ(earlier.body.at("design").at("seed"), 3);
  EXPECT_EQ(alice_->get("/api/projects/d/status").body.at("design").at("id"), second.body.at("id"));
  EXPECT_EQ(alice_->get("/api/projects/d/status?design=999").status, 404);
  EXPECT_EQ(alice_->get("/api/projects/d/status?design=x").status, 400);
  EXPECT_EQ(bob_->get("/api/projects/d/status?design=" + id).status, 404);

  // Bob reaches none of it: every delete is a 404, as for a project that does not exist.
  EXPECT_EQ(bob_->post("/api/projects/d/designs/" + id + "/delete", json::object()).status, 404);
  EXPECT_EQ(bob_->post("/api/projects/d/software/walker/delete", json::object()).status, 404);
  EXPECT_EQ(bob_->post("/api/projects/d/delete", {{"confirm", "d"}}).status, 404);
  EXPECT_TRUE(std::filesystem::is_directory(folder));

  // Alice deletes one saved program, then one design: the others stay.
  EXPECT_EQ(alice_->post("/api/projects/d/software/walker/delete", json::object()).status, 200);
  EXPECT_EQ(alice_->post("/api/projects/d/software/walker/delete", json::object()).status, 404);
  EXPECT_EQ(alice_->post("/api/projects/d/software/..%2Fmissions/delete", json::object()).status, 404);
  ASSERT_EQ(alice_->get("/api/projects/d/software").body.size(), 1u);
  EXPECT_EQ(alice_->get("/api/projects/d/software").body.at(0).at("name"), "other");
  EXPECT_EQ(alice_->post("/api/projects/d/designs/" + id + "/delete", json::object()).status, 200);
  EXPECT_FALSE(std::filesystem::exists(folder));
  EXPECT_EQ(alice_->get("/api/projects/d/designs").body.size(), 1u);
  EXPECT_EQ(alice_->post("/api/projects/d/designs/" + id + "/delete", json::object()).status, 404);

  // A project goes only when its name is confirmed, and only it.
  const Answer unconfirmed = alice_->post("/api/projects/d/delete", {{"confirm", "kept"}});
  EXPECT_EQ(unconfirmed.status, 400);
  EXPECT_NE(unconfirmed.text.find("confirm with its name"), std::string::npos) << unconfirmed.text;
  EXPECT_EQ(alice_->post("/api/projects/d/delete", json::object()).status, 400);
  ASSERT_EQ(alice_->post("/api/projects/d/delete", {{"confirm", "d"}}).status, 200);
  EXPECT_FALSE(std::filesystem::exists(root_ / "home" / "users" / "alice" / "projects" / "d"));
  ASSERT_EQ(alice_->get("/api/projects").body.size(), 1u);
  EXPECT_EQ(alice_->get("/api/projects").body.at(0).at("name"), "kept");
  EXPECT_EQ(alice_->get("/api/projects/d/status").status, 404);
}

TEST_F(WebServer, TwoFinishedDesignsAreComparedOnTheSameSeedsWithAPairedTest) {
  alice_project("c", "1100");
  std::vector<std::int64_t> ids;
  for (int seed : {3, 4}) {
    const Answer started = alice_->post("/api/projects/c/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", seed}});
    ASSERT_EQ(started.status, 200) << started.text;
    ids.push_back(started.body.at("id").get<std::int64_t>());
    ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/c/status").body.at("design").at("state") == "finished"; },
                           std::chrono::seconds(300)));
  }
  const Answer compared = alice_->post("/api/projects/c/compare", {{"designs", ids}, {"seeds", "21-30"}});
  ASSERT_EQ(compared.status, 200) << compared.text;
  const std::string mission = alice_->get("/api/projects").body.at(0).at("mission");
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = 21; s <= 30; ++s) seeds.push_back(s);
  std::vector<std::vector<double>> expected;
  for (std::size_t side = 0; side < 2; ++side) {
    const json& d = compared.body.at("designs").at(side);
    EXPECT_EQ(d.at("design"), ids[side]);
    const auto rows = alice_->get("/api/projects/c/designs").body;
    std::string best;
    for (const json& row : rows)
      if (row.at("id") == ids[side]) best = row.at("best_configuration");
    EXPECT_EQ(d.at("control_software"), best);
    expected.push_back(app::score_seeds(load_mission(mission), parse_control_software(best), seeds));
    ASSERT_EQ(d.at("runs").size(), 10u);
    for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(d.at("runs").at(i).at("score").get<double>(), expected[side][i]);
  }
  const json& test = compared.body.at("wilcoxon");
  if (expected[0] != expected[1]) {
    EXPECT_DOUBLE_EQ(test.at("p_value").get<double>(), statistics::wilcoxon_signed_rank(expected[0], expected[1]).p_value);
  } else {
    EXPECT_TRUE(test.contains("note"));
  }
  EXPECT_EQ(bob_->post("/api/projects/c/compare", {{"designs", ids}}).status, 404);
  EXPECT_EQ(alice_->post("/api/projects/c/compare", {{"designs", {ids[0]}}}).status, 400);
  EXPECT_EQ(alice_->post("/api/projects/c/compare", {{"designs", {ids[0], 999}}}).status, 404);
  EXPECT_EQ(alice_->post("/api/projects/c/compare", {{"designs", ids}, {"seeds", "1-500"}}).status, 400);

  // Either one goes to ARGoS as `mission export-argos` and `export --argos` give it.
  const Answer exported = alice_->post("/api/projects/c/argos", {{"design", ids[0]}});
  ASSERT_EQ(exported.status, 200) << exported.text;
  const Mission loaded = load_mission(mission);
  const std::string best0 = compared.body.at("designs").at(0).at("control_software");
  const argos::LegacyString legacy = argos::to_legacy_string(parse_control_software(best0));
  argos::ExperimentOptions with_default;  // the design's FSM is the controller's default
  with_default.default_fsm_config = legacy.text.substr(std::string("--fsm-config ").size());
  EXPECT_EQ(exported.body.at("experiment"), argos::argos_experiment(loaded, with_default).xml);
  EXPECT_EQ(exported.body.at("file_name"), loaded.name + ".argos");
  EXPECT_EQ(exported.body.at("argos").at("config"), legacy.text);
  EXPECT_EQ(exported.body.at("command"), "automode_main -n -c " + loaded.name + ".argos --seed 1 " + legacy.text);
  EXPECT_EQ(bob_->post("/api/projects/c/argos", {{"design", ids[0]}}).status, 404);
  EXPECT_EQ(alice_->post("/api/projects/c/argos", {{"design", 999}}).status, 404);
}

/// A protocol of one short mission file, two conditions, one design each.
std::string tiny_protocol(const std::string& name, const std::string& mission, long long budget) {
  const json conditions = json::array({{{"name", "fsm"}, {"architectures", {"fsm"}}, {"flavours", {"chocolate"}}},
                                       {{"name", "bt"}, {"architectures", {"bt"}}, {"flavours", {"maple"}}}});
  return json{{"name", name}, {"designs", 1}, {"assessment_seeds", 3},
              {"missions", {{{"mission", mission}, {"budget", budget}, {"conditions", conditions}}}}}.dump();
}

TEST_F(WebServer, AnExperimentIsStartedFollowedStoppedAndResumedFromThePageByItsOwnerOnly) {
  alice_project("x", "1100");
  const std::string mission = alice_->get("/api/projects").body.at(0).at("mission");

  // The built-in protocols are offered whole.
  const Answer protocols = alice_->get("/api/protocols");
  ASSERT_EQ(protocols.status, 200);
  ASSERT_EQ(protocols.body.size(), 4u);
  EXPECT_EQ(protocols.body.at(0).at("name"), "validation");
  EXPECT_EQ(protocols.body.at(3).at("name"), "methods");
  EXPECT_FALSE(protocols.body.at(0).at("protocol").at("missions").empty());

  // Planned only: nothing recorded.
  const Answer plan = alice_->post("/api/projects/x/experiments", {{"text", tiny_protocol("quick", mission, 1500)}, {"dry_run", true}});
  ASSERT_EQ(plan.status, 200) << plan.text;
  EXPECT_EQ(plan.body.at("designs").size(), 2u) << plan.text;
  EXPECT_TRUE(alice_->get("/api/projects/x/experiments").body.empty());

  // Bad protocols get the protocol's one line; another user's mission file is out of reach.
  const Answer bad = alice_->post("/api/projects/x/experiments", {{"text", R"({"name": "q", "designs": 0, "missions": []})"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.text.find("designs"), std::string::npos) << bad.text;
  EXPECT_EQ(alice_->post("/api/projects/x/experiments", {{"protocol", "no-such"}}).status, 400);
  {
    const auto folder = root_ / "home" / "users" / "bob" / "projects" / "b";
    std::filesystem::create_directories(folder);
    ASSERT_EQ(bob_->post("/api/projects", {{"name", "b"}, {"mission", write_short_mission(folder).string()}, {"budget", "2000"}}).status, 200);
    const std::string bobs = bob_->get("/api/projects").body.at(0).at("mission");
    EXPECT_EQ(alice_->post("/api/projects/x/experiments", {{"text", tiny_protocol("theft", bobs, 1500)}}).status, 404);
    EXPECT_EQ(bob_->post("/api/projects/x/experiments", {{"text", tiny_protocol("quick", bobs, 1500)}}).status, 404);
  }
  EXPECT_TRUE(alice_->get("/api/projects/x/experiments").body.empty());

  // Started, followed while its first design races, stopped, resumed to the end. Under a
  // sanitizer a tick takes about ten times as long and the project's mission lasts a fifth
  // (kShortMissionSeconds): the same runs race about twice as long as in Release.
  const long long budget = 5000;
  const Answer started = alice_->post("/api/projects/x/experiments", {{"text", tiny_protocol("quick", mission, budget)}});
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body.at("experiment").at("state"), "running");
  EXPECT_TRUE(started.body.at("experiment").at("running_here").get<bool>());
  EXPECT_EQ(alice_->post("/api/projects/x/experiments", {{"text", tiny_protocol("other", mission, 1500)}}).status, 409)
      << "one experiment per user on the server";
  ASSERT_TRUE(wait_until([&] {
    const json list = alice_->get("/api/projects/x/experiments").body;
    return list.at(0).contains("current") && list.at(0).at("current").value("runs_used", 0) > 0;
  }, std::chrono::seconds(120)));
  EXPECT_EQ(alice_->get("/api/projects/x/status").body.at("experiments").at(0).at("running_here"), true);
  // Its design under way opens as a design does in the monitor.
  const Answer current = alice_->get("/api/projects/x/experiments/quick/current");
  ASSERT_EQ(current.status, 200) << current.text;
  EXPECT_EQ(current.body.at("design").at("budget"), budget);
  EXPECT_GT(current.body.at("progress").at("experiments_used").get<int>(), 0);
  EXPECT_TRUE(current.body.contains("race_log"));
  EXPECT_EQ(bob_->get("/api/projects/x/experiments/quick/current").status, 404);
  EXPECT_EQ(alice_->get("/api/projects/x/experiments/none/current").status, 404);
  EXPECT_EQ(bob_->post("/api/projects/x/experiments/quick/stop", json::object()).status, 404);
  ASSERT_EQ(alice_->post("/api/projects/x/experiments/quick/stop", json::object()).status, 200);
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/x/experiments").body.at(0).at("state") == "interrupted"; },
                         std::chrono::seconds(120)));
  EXPECT_EQ(alice_->post("/api/projects/x/experiments/quick/stop", json::object()).status, 409);
  EXPECT_EQ(bob_->post("/api/projects/x/experiments/quick/resume", json::object()).status, 404);
  const Answer resumed = alice_->post("/api/projects/x/experiments/quick/resume", json::object());
  ASSERT_EQ(resumed.status, 200) << resumed.text;
  EXPECT_TRUE(resumed.body.at("resumed").get<bool>());
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/x/experiments").body.at(0).at("state") == "finished"; },
                         std::chrono::seconds(600)));
  const json done = alice_->get("/api/projects/x/experiments").body.at(0);
  EXPECT_EQ(done.at("designs_done"), 2);
  EXPECT_FALSE(done.at("running_here").get<bool>());
  EXPECT_EQ(alice_->get("/api/projects/x/experiments/quick/current").status, 404) << "every design is done";
  const Answer designs = alice_->get("/api/projects/x/experiments/quick/designs.csv");
  EXPECT_EQ(designs.status, 200);
  EXPECT_EQ(std::count(designs.text.begin(), designs.text.end(), '\n'), 3) << designs.text;  // a header, two designs
  EXPECT_EQ(bob_->get("/api/projects/x/experiments/quick/designs.csv").status, 404);
  // Each design it made opens as a design does, by its id in the report.
  const json report = alice_->get("/api/projects/x/experiments/quick/report.json").body;
  ASSERT_EQ(report.at("designs").size(), 2u);
  for (const json& d : report.at("designs")) {
    const std::string route = "/api/projects/x/experiments/quick/designs/" + std::to_string(d.at("id").get<int>());
    const Answer shown = alice_->get(route + "?race_log=false");
    ASSERT_EQ(shown.status, 200) << shown.text;
    EXPECT_EQ(shown.body.at("design").at("state"), "finished");
    EXPECT_EQ(shown.body.at("design").at("best_configuration"), d.at("configuration"));
    EXPECT_EQ(shown.body.at("design").at("seed"), d.at("seed"));
    EXPECT_FALSE(shown.body.contains("race_log"));
    EXPECT_FALSE(shown.body.at("convergence").empty());
    EXPECT_EQ(bob_->get(route).status, 404);
  }
  const Answer unknown = alice_->get("/api/projects/x/experiments/quick/designs/99999");
  EXPECT_EQ(unknown.status, 404);
  EXPECT_EQ(unknown.body.at("error"), "experiment quick has no design 99999");
}

TEST_F(WebServer, OneUserRunsAtMostTwoDesignsHereAndTheThirdChangesNothing) {
  const json fsm{{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 3}};
  for (const char* name : {"p1", "p2", "p3"}) alice_project(name, "200000");
  ASSERT_EQ(alice_->post("/api/projects/p1/designs", fsm).status, 200);
  ASSERT_EQ(alice_->post("/api/projects/p2/designs", fsm).status, 200);
  const Answer third = alice_->post("/api/projects/p3/designs", fsm);
  EXPECT_EQ(third.status, 409) << third.text;
  EXPECT_NE(third.body.value("error", "").find("2 designs running"), std::string::npos) << third.text;
  EXPECT_TRUE(alice_->get("/api/projects/p3/designs").body.empty()) << "refused before anything is recorded";
  // Another user is not held back by Alice's.
  {
    const auto folder = root_ / "home" / "users" / "bob" / "projects" / "b";
    std::filesystem::create_directories(folder);
    const Answer made = bob_->post("/api/projects", {{"name", "b"}, {"mission", write_short_mission(folder).string()}, {"budget", "200000"}});
    ASSERT_EQ(made.status, 200) << made.text;
    EXPECT_EQ(bob_->post("/api/projects/b/designs", fsm).status, 200);
  }
  // A design asked to stop no longer counts: the third starts at once.
  ASSERT_EQ(alice_->post("/api/projects/p1/designs/stop", json::object()).status, 200);
  EXPECT_EQ(alice_->post("/api/projects/p3/designs", fsm).status, 200);
  for (const char* name : {"p2", "p3"}) alice_->post(std::string("/api/projects/") + name + "/designs/stop", json::object());
  bob_->post("/api/projects/b/designs/stop", json::object());
}

TEST_F(WebServer, ASecondServerCannotTakeAPortAlreadyServed) {
  web::WebServer second({"127.0.0.1", server_->port(), {}, root_ / "home", {}, {}});
  EXPECT_THROW(second.bind(), std::runtime_error);
  EXPECT_EQ(alice_->get("/api/session").status, 200);
}

TEST_F(WebServer, TheServerBindsTheLoopbackAddressByDefault) {
  EXPECT_EQ(web::WebServerOptions{}.host, "127.0.0.1");
  // The command's own default, as a user starts it.
  const std::string out = [&] {
    const std::string command = "SWARMDESIGN_HOME='" + (root_ / "home").string() + "' timeout 3 " + ::sd::test::swarmdesign_binary() +
                                " run-exp --port 0 --web-root '" + root_.string() + "' 2>&1";
    std::string text;
    FILE* pipe = ::popen(command.c_str(), "r");
    char buffer[256];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    if (pipe) ::pclose(pipe);
    return text;
  }();
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(http://127\.0\.0\.1:\d+/)"))) << out;
  EXPECT_EQ(out.find("Warning"), std::string::npos) << out;
}

/// One line naming `field`, with status 400.
void expect_field_refused(const Answer& a, const std::string& field) {
  EXPECT_EQ(a.status, 400) << a.text;
  ASSERT_TRUE(a.body.is_object()) << a.text;
  const std::string error = a.body.value("error", "");
  EXPECT_EQ(error.rfind(field, 0), 0u) << "the error names " << field << ": " << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST_F(WebServer, AnExecRunsInAPseudoRealitySampleAndScoresWhatThatRobotModelScores) {
  alice_project("gap");
  const std::string mission = alice_->get("/api/projects").body.at(0).at("mission");
  const Answer listed = alice_->get("/api/pseudo-realities");
  ASSERT_EQ(listed.status, 200) << listed.text;
  std::vector<std::string> names;
  for (const json& p : listed.body) names.push_back(p.at("name"));
  EXPECT_NE(std::find(names.begin(), names.end(), "sampled-around"), names.end()) << listed.text;

  const Answer started =
      alice_->post("/api/runs", {{"text", kFsm}, {"mission", mission}, {"seed", 3}, {"pseudo_reality", "sampled-around"}, {"sample", 4}});
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body.at("pseudo_reality").at("sample"), 4);
  const Answer stream = alice_->stream("/api/runs/" + std::to_string(started.body.at("id").get<std::int64_t>()) + "/stream");
  const auto end = events(stream.text, "end");
  ASSERT_EQ(end.size(), 1u) << stream.text.substr(0, 300);
  const Mission design_model = load_mission(mission);
  const Mission sample = app::in_pseudo_reality(design_model, *builtin_pseudo_reality("sampled-around"), 4);
  EXPECT_EQ(json(sample.robot.wheel_noise), started.body.at("pseudo_reality").at("robot").at("wheel_noise"));
  EXPECT_NE(sample.robot.wheel_noise, design_model.robot.wheel_noise) << "the sample is another robot model";
  const double evaluated = app::score_seeds(sample, parse_control_software(kFsm), {3}).at(0);
  const double streamed = end[0].at("score").get<double>();
  EXPECT_EQ(std::memcmp(&streamed, &evaluated, sizeof(double)), 0) << streamed << " vs " << evaluated;
  // Without one, the run is the design model's, as before.
  EXPECT_TRUE(alice_->post("/api/runs", {{"text", kFsm}, {"mission", mission}, {"seed", 3}}).body.at("pseudo_reality").is_null());

  const json run{{"text", kFsm}, {"mission", mission}, {"seed", 3}};
  const auto with = [&](json extra) {
    json body = run;
    body.update(extra);
    return alice_->post("/api/runs", body);
  };
  expect_field_refused(with({{"pseudo_reality", "no-such-world"}}), "pseudo_reality");
  expect_field_refused(with({{"pseudo_reality", "sampled-around"}, {"sample", 0}}), "sample");
  expect_field_refused(with({{"pseudo_reality", "sampled-around"}, {"sample", "x"}}), "sample");
  expect_field_refused(with({{"sample", 2}}), "sample");
  // Another user's file, or one outside any project, is refused in the same words as a missing one.
  const auto alices = root_ / "home" / "users" / "alice" / "projects" / "gap" / "world.json";
  std::ofstream(alices) << R"({"name": "mine", "knobs": {"wheel_noise": 0.2}})";
  EXPECT_EQ(with({{"pseudo_reality", alices.string()}, {"sample", 1}}).status, 200);
  const Answer from_bob = bob_->post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", 3}, {"pseudo_reality", alices.string()}});
  expect_field_refused(from_bob, "pseudo_reality");
  const auto elsewhere = (root_ / "home" / "users" / "alice" / "none.json").string();
  const Answer missing = bob_->post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", 3}, {"pseudo_reality", elsewhere}});
  // Both quoted relative to the home: no message shows where the server keeps it.
  const std::string home = (root_ / "home").string() + "/";
  std::string said = from_bob.body.value("error", "");
  ASSERT_EQ(said.find(home), std::string::npos) << said;
  const std::string quoted = alices.string().substr(home.size()), quoted_elsewhere = elsewhere.substr(home.size());
  ASSERT_NE(said.find(quoted), std::string::npos) << said;
  said.replace(said.find(quoted), quoted.size(), quoted_elsewhere);
  EXPECT_EQ(missing.body.value("error", ""), said);
}

TEST_F(WebServer, ADesignsBestIsAssessedInAPseudoRealityKeptInItsFolderAndShownToItsOwnerOnly) {
  const auto folder = root_ / "home" / "users" / "alice" / "projects" / "r";
  std::filesystem::create_directories(folder);
  ASSERT_EQ(alice_->post("/api/projects", {{"name", "r"}, {"mission", write_short_mission(folder, 2).string()}, {"budget", "1100"}}).status, 200);
  const Answer started = alice_->post("/api/projects/r/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 3}});
  ASSERT_EQ(started.status, 200) << started.text;
  const std::int64_t id = started.body.at("id");
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/r/status").body.at("design").at("state") == "finished"; },
                         std::chrono::seconds(120)));
  const std::string route = "/api/projects/r/designs/" + std::to_string(id) + "/assessment";
  EXPECT_EQ(alice_->get(route).status, 404) << "not assessed yet";

  const Answer assessed = alice_->post(route, {{"pseudo_reality", "sampled-around"}, {"samples", "1-3"}, {"seeds", "1-4"}});
  ASSERT_EQ(assessed.status, 200) << assessed.text;
  const json& software = assessed.body.at("software").at(0);
  EXPECT_EQ(assessed.body.at("samples").size(), 3u);
  EXPECT_EQ(assessed.body.at("seeds").size(), 4u);
  EXPECT_EQ(software.at("runs").size(), 4u * (1 + 3));
  for (const char* key : {"design_mean", "pseudo_reality_mean", "drop", "drop_ci95", "relative_drop", "p_value"})
    EXPECT_TRUE(software.contains(key)) << key;
  const auto rows = alice_->get("/api/projects/r/designs").body;
  for (const json& row : rows) {
    if (row.at("id") == id) {
      EXPECT_EQ(software.at("control_software"), row.at("best_configuration"));
    }
  }
  // Kept in the design's folder, and served until assessed again.
  const auto file = folder / "designs" / std::to_string(id) / "assessment.json";
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  const Answer again = alice_->get(route);
  ASSERT_EQ(again.status, 200);
  EXPECT_EQ(again.body, assessed.body);

  // Bob reaches none of it; bad requests say which field is wrong; no CSRF token, no assessment.
  EXPECT_EQ(bob_->get(route).status, 404);
  EXPECT_EQ(bob_->post(route, {{"pseudo_reality", "sampled-around"}}).status, 404);
  EXPECT_EQ(alice_->post(route, {{"pseudo_reality", "sampled-around"}}, false).status, 403);
  EXPECT_EQ(alice_->post("/api/projects/r/designs/999/assessment", {{"pseudo_reality", "sampled-around"}}).status, 404);
  expect_field_refused(alice_->post(route, {{"samples", "1-2"}}), "pseudo_reality");
  expect_field_refused(alice_->post(route, {{"pseudo_reality", "no-such-world"}}), "pseudo_reality");
  // The field's first name still works for one release.
  expect_field_refused(alice_->post(route, {{"spec", "no-such-world"}}), "pseudo_reality");
  expect_field_refused(alice_->post(route, {{"pseudo_reality", "sampled-around"}, {"samples", "0"}}), "samples");
  expect_field_refused(alice_->post(route, {{"pseudo_reality", "sampled-around"}, {"seeds", "x"}}), "seeds");
  expect_field_refused(alice_->post(route, {{"pseudo_reality", "sampled-around"}, {"samples", "1-20"}, {"seeds", "1-1000"}}), "samples");
  EXPECT_EQ(alice_->get(route).body, assessed.body) << "a refused request leaves the last assessment";
}

TEST_F(WebServer, ARobustDesignIsStartedWithItsPseudoRealitiesAndBadOnesAreRefusedBeforeAnythingIsRecorded) {
  const auto folder = root_ / "home" / "users" / "alice" / "projects" / "rb";
  std::filesystem::create_directories(folder);
  ASSERT_EQ(alice_->post("/api/projects", {{"name", "rb"}, {"mission", write_short_mission(folder, 2).string()}, {"budget", "1100"}}).status, 200);
  const json space = {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 4}};
  auto with = [&](json extra) {
    json body = space;
    body.update(extra);
    return body;
  };
  EXPECT_EQ(alice_->post("/api/projects/rb/designs", with({{"pseudo_reality", "no-such-world"}})).status, 400);
  EXPECT_EQ(alice_->post("/api/projects/rb/designs", with({{"pseudo_reality", "sampled-around"}, {"pseudo_reality_samples", "0-2"}})).status, 400);
  EXPECT_EQ(alice_->post("/api/projects/rb/designs", with({{"pseudo_reality_samples", "1-2"}})).status, 400);
  // Another user's file is refused as any missing one, and names nothing of it.
  const auto bobs = root_ / "home" / "users" / "bob" / "world.json";
  std::filesystem::create_directories(bobs.parent_path());
  std::ofstream(bobs) << R"({"knobs": {"wheel_noise": 0.2}})";
  const Answer outside = alice_->post("/api/projects/rb/designs", with({{"pseudo_reality", bobs.string()}}));
  EXPECT_GE(outside.status, 400);
  EXPECT_LT(outside.status, 500);
  EXPECT_EQ(outside.text.find("wheel_noise"), std::string::npos);
  EXPECT_TRUE(alice_->get("/api/projects/rb/designs").body.empty()) << "nothing recorded for a refused request";

  // Started with the field's first name (pseudo_realities), still accepted for one release.
  const Answer started = alice_->post("/api/projects/rb/designs", with({{"pseudo_realities", "sampled-around"}, {"pseudo_reality_samples", "101-103"}}));
  ASSERT_EQ(started.status, 200) << started.text;
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/rb/status").body.at("design").at("state") == "finished"; },
                         std::chrono::seconds(120)));
  const auto db = folder / "designs" / std::to_string(started.body.at("id").get<std::int64_t>());
  const storage::DesignMeta meta = storage::DesignStore::open(db).meta();
  EXPECT_EQ(meta.pseudo_reality, "sampled-around");
  EXPECT_EQ(meta.pseudo_reality_samples, "101-103");
}

TEST_F(WebServer, ADesignRacedByAnotherMethodIsStartedWithItAndAnUnknownOneIsRefused) {
  const auto folder = root_ / "home" / "users" / "alice" / "projects" / "ls";
  std::filesystem::create_directories(folder);
  ASSERT_EQ(alice_->post("/api/projects", {{"name", "ls"}, {"mission", write_short_mission(folder, 2).string()}, {"budget", "1100"}}).status, 200);
  const json space = {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 4}};
  json unknown = space;
  unknown["method"] = "evostick";
  const Answer refused = alice_->post("/api/projects/ls/designs", unknown);
  EXPECT_EQ(refused.status, 400);
  EXPECT_NE(refused.text.find("unknown design method 'evostick'"), std::string::npos) << refused.text;
  EXPECT_TRUE(alice_->get("/api/projects/ls/designs").body.empty()) << "nothing recorded for a refused request";
  // The form's minimum follows the method; the list of methods comes with it.
  const Answer form = alice_->get("/api/design-space?architectures=fsm&flavours=chocolate&method=local-search");
  ASSERT_EQ(form.status, 200) << form.text;
  EXPECT_EQ(form.body.at("method"), "local-search");
  EXPECT_EQ(form.body.at("methods").size(), 3u);

  json body = space;
  body["method"] = "local-search";
  const Answer started = alice_->post("/api/projects/ls/designs", body);
  ASSERT_EQ(started.status, 200) << started.text;
  EXPECT_EQ(started.body.at("method"), "local-search");
  ASSERT_TRUE(wait_until([&] { return alice_->get("/api/projects/ls/status").body.at("design").at("state") == "finished"; },
                         std::chrono::seconds(120)));
  const auto db = folder / "designs" / std::to_string(started.body.at("id").get<std::int64_t>());
  EXPECT_EQ(storage::DesignStore::open(db).meta().method, "local-search");
  EXPECT_EQ(alice_->get("/api/projects/ls/designs").body.at(0).at("method"), "local-search");
}

}  // namespace
}  // namespace sd::test
