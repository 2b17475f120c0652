// The web server with everything at once, as a lab's server lives: a design running in the
// background, two users' Exec runs each watched by several tabs, and pages polling the
// design's status meanwhile; then the server shut down under the running design. Each part
// has its own test in web_server_test.cpp; this one is for the threads meeting (TSan runs it,
// scripts/sanitizers.sh).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <thread>
#include <vector>

#include "app/accounts.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"
#include "web/web_client.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

constexpr std::size_t kTabs = 6;  // per run
constexpr int kPollers = 3;

/// How many times `head` opens an event of the stream.
std::size_t count(const std::string& stream, const std::string& event) {
  const std::string head = "event: " + event + "\n";
  std::size_t n = 0;
  for (std::size_t at = stream.find(head); at != std::string::npos; at = stream.find(head, at + 1)) ++n;
  return n;
}

/// The `end` event's line (its data: the score), or "" when the stream has none.
std::string end_of(const std::string& stream) {
  const auto at = stream.find("event: end\ndata: ");
  return at == std::string::npos ? "" : stream.substr(at, stream.find('\n', at + 17) - at);
}

TEST(WebConcurrency, ABackgroundDesignRunsWatchersAndPollersMeetAndTheServerStopsCleanly) {
  const auto root = std::filesystem::temp_directory_path() / (std::string("sd-web-concurrency-") + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  {
    app::Home home(root / "home");
    app::sign_up(home, "alice", "alice-password");
    app::sign_up(home, "bob", "bob-password");
  }
  std::optional<RunningServer> server(std::in_place, root / "home");
  WebClient alice(server->port()), bob(server->port());
  ASSERT_TRUE(alice.sign_in("alice", "alice-password"));
  ASSERT_TRUE(bob.sign_in("bob", "bob-password"));

  const auto folder = root / "home" / "users" / "alice" / "projects" / "d";
  std::filesystem::create_directories(folder);
  const Answer project =
      alice.post("/api/projects", {{"name", "d"}, {"mission", write_short_mission(folder).string()}, {"budget", "20000"}});
  ASSERT_EQ(project.status, 200) << project.text;
  const Answer design = alice.post("/api/projects/d/designs", {{"flavours", "chocolate"}, {"architectures", "fsm"}, {"seed", 3}});
  ASSERT_EQ(design.status, 200) << design.text;

  const Answer a = alice.post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", 5}});
  const Answer b = bob.post("/api/runs", {{"text", kFsm}, {"mission", "aac"}, {"seed", 6}});
  ASSERT_EQ(a.status, 200) << a.text;
  ASSERT_EQ(b.status, 200) << b.text;

  std::vector<std::string> seen(2 * kTabs);
  std::atomic<int> watching{static_cast<int>(seen.size())}, bad_polls{0}, polls{0};
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&, t] {
      const bool alices = t < kTabs;
      WebClient tab(server->port(), alices ? alice : bob);
      const Answer s = tab.stream(std::string("/api/runs/") + std::to_string((alices ? a : b).body.at("id").get<std::int64_t>()) + "/stream");
      seen[t] = s.status == 200 ? s.text : std::to_string(s.status);
      --watching;
    });
  for (int p = 0; p < kPollers; ++p)
    threads.emplace_back([&] {
      WebClient page(server->port(), alice);
      while (watching > 0) {  // the Designs tab, polling while the runs are watched
        const Answer status = page.get("/api/projects/d/status");
        const Answer list = page.get("/api/projects/d/designs");
        ++polls;
        if (status.status != 200 || list.status != 200 || status.body.at("design").at("id") != design.body.at("id"))
          ++bad_polls;
      }
    });
  for (auto& t : threads) t.join();

  EXPECT_GT(polls.load(), 0);
  EXPECT_EQ(bad_polls.load(), 0);
  for (std::size_t t = 0; t < seen.size(); ++t) {
    const std::size_t first = t < kTabs ? 0 : kTabs;  // each run's first tab is its reference
    EXPECT_EQ(count(seen[t], "end"), 1u) << "tab " << t << ": " << seen[t].substr(0, 200);
    EXPECT_EQ(count(seen[t], "frames"), count(seen[first], "frames")) << "tab " << t;
    EXPECT_EQ(end_of(seen[t]), end_of(seen[first])) << "tab " << t;
  }

  // Shut down under the design: it stops at its next race step and is left resumable, never
  // "running" for a server that is gone.
  server.reset();
  {
    app::Home home(root / "home");
    const storage::User user = app::sign_in_here(home, "alice", "alice-password").user;
    storage::Designs designs(home.workspace(), storage::Projects(home.workspace(), user).get("d"));
    const auto state = designs.latest()->state;
    EXPECT_TRUE(state == storage::DesignState::interrupted || state == storage::DesignState::finished)
        << storage::to_string(state);
  }
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace sd::test
