// Sign-up on a lab's server (issue #56): closed unless the server is run with --sign-up invite
// or open; an administrator's one-time invitation signs one person up, once, before it expires
// or is revoked. Tried as an attacker would: no code, a wrong, used, expired or revoked one, a
// plain user inviting, an empty home whose first account would administer it, and guessing
// codes in bulk until the address is locked out. A refusal makes no account and uses up no
// invitation.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "web/web_client.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using nlohmann::json;

class sign_up : public WorkflowTest {
 protected:
  void start_server(app::SignUpPolicy policy) {
    web::WebServerOptions options;
    options.home = home();
    options.sign_up = policy;
    server_.emplace(options);
  }
  void TearDown() override {
    server_.reset();
    WorkflowTest::TearDown();
  }
  WebClient client() { return WebClient(server_->port()); }
  std::string invitation() { return json::parse(run_ok({"admin", "invite", "--json"})).at("code"); }
  std::string accounts() { return query("SELECT group_concat(name, ',') FROM (SELECT name FROM users ORDER BY name)"); }
  static json request(const std::string& name, const std::string& code) {
    return {{"name", name}, {"password", name + "-secret-pw"}, {"invitation", code}};
  }
  std::optional<RunningServer> server_;
};

TEST_F(sign_up, IsClosedByDefaultAndOnAHomeWithoutItsAdministrator) {
  start_server(app::SignUpPolicy::open);
  WebClient page = client();
  const Answer first = page.sign_up(request("eve", ""));
  EXPECT_EQ(first.status, 403);
  EXPECT_NE(first.text.find("no administrator yet"), std::string::npos) << first.text;
  EXPECT_EQ(accounts(), "<null>") << "whoever reached the page first must not administer it";

  user_with_active_project("boss", "lab");
  ASSERT_EQ(web::WebServerOptions{}.sign_up, app::SignUpPolicy::closed) << "the default";
  start_server(app::SignUpPolicy::closed);
  EXPECT_EQ(client().get("/api/sign-up").body, (json{{"policy", "closed"}}));
  const Answer closed = client().sign_up(request("eve", invitation()));
  EXPECT_EQ(closed.status, 403);
  EXPECT_NE(closed.text.find("sign-up is closed on this server"), std::string::npos) << closed.text;
  EXPECT_EQ(accounts(), "boss");

  start_server(app::SignUpPolicy::open);
  WebClient anyone = client();
  ASSERT_EQ(anyone.sign_up(request("ann", "")).status, 200);
  EXPECT_EQ(anyone.get("/api/session").body.at("user"), "ann");
  EXPECT_EQ(anyone.get("/api/session").body.at("admin"), false);
  expect_error(run({"run-exp", "--sign-up", "sometimes"}), 2, "--sign-up 'sometimes': closed, invite or open");
}

TEST_F(sign_up, AnInvitationSignsUpOnePersonOnceAndNothingElseDoes) {
  user_with_active_project("boss", "lab");
  start_server(app::SignUpPolicy::invite);
  EXPECT_EQ(client().get("/api/sign-up").body, (json{{"policy", "invite"}}));
  const std::string code = invitation();
  ASSERT_EQ(code.size(), 24u);

  // Refused, one line each, and the invitation stays unused.
  for (const std::string& wrong : {std::string(), std::string("not-a-code"), code.substr(1) + "x"}) {
    const Answer refused = client().sign_up(request("ann", wrong));
    EXPECT_EQ(refused.status, 403) << wrong;
    EXPECT_EQ(refused.body.value("error", ""), "this invitation is not valid (used, expired or revoked): ask for another");
  }
  const Answer weak = client().sign_up({{"name", "ann"}, {"password", "short"}, {"invitation", code}});
  EXPECT_EQ(weak.status, 400);
  EXPECT_NE(weak.text.find("password"), std::string::npos) << weak.text;
  EXPECT_EQ(client().sign_up({{"name", "bad name!"}, {"password", "ann-secret-pw"}, {"invitation", code}}).status, 400);
  EXPECT_EQ(client().sign_up({{"name", "boss"}, {"password", "boss-secret-pw2"}, {"invitation", code}}).status, 409)
      << "a name that is taken";
  EXPECT_EQ(client().sign_up({{"name", "ann"}, {"invitation", code}}).status, 400) << "no password";
  EXPECT_EQ(accounts(), "boss");
  EXPECT_EQ(json::parse(run_ok({"admin", "invitations", "--json"})).at(0).at("state"), "open");

  WebClient ann = client();
  const Answer made = ann.sign_up(request("ann", code));
  ASSERT_EQ(made.status, 200) << made.text;
  EXPECT_EQ(ann.get("/api/session").body.at("user"), "ann") << "signed in by the sign-up";
  EXPECT_EQ(ann.get("/api/session").body.at("admin"), false);
  EXPECT_EQ(client().sign_up(request("bob", code)).status, 403) << "once only";
  const json listed = json::parse(run_ok({"admin", "invitations", "--json"}));
  EXPECT_EQ(listed.at(0).at("state"), "used");
  EXPECT_EQ(listed.at(0).at("used_by"), "ann");
  EXPECT_EQ(listed.at(0).at("created_by"), "boss");
  EXPECT_EQ(accounts(), "ann,boss");

  // A plain user invites nobody, from either front end.
  EXPECT_EQ(ann.post("/api/admin/invitations", json::object()).status, 403);
  EXPECT_EQ(ann.get("/api/admin/invitations").status, 403);
  sign_in("ann", "ann-secret-pw");
  expect_error(run({"admin", "invite"}), 1, "only an administrator");
  sign_in("boss", "boss-secret-pw");

  // Revoked from the page, expired by time: refused alike.
  WebClient boss = client();
  ASSERT_TRUE(boss.sign_in("boss", "boss-secret-pw"));
  const Answer second = boss.post("/api/admin/invitations", {{"days", 3}});
  ASSERT_EQ(second.status, 200) << second.text;
  EXPECT_EQ(boss.post("/api/admin/invitations", {{"days", 365}}).status, 400);
  EXPECT_EQ(boss.post("/api/admin/invitations", {{"days", "many"}}).status, 400);
  const std::string revoke = "/api/admin/invitations/" + std::to_string(second.body.at("id").get<int>()) + "/revoke";
  ASSERT_EQ(boss.post(revoke, json::object()).status, 200);
  EXPECT_EQ(client().sign_up(request("cid", second.body.at("code"))).status, 403);
  // Kept in the list as revoked, and revoked once.
  const json after_revoke = json::parse(run_ok({"admin", "invitations", "--json"}));
  EXPECT_EQ(after_revoke.at(1).at("state"), "revoked");
  EXPECT_TRUE(after_revoke.at(1).at("revoked_at").is_number());
  EXPECT_EQ(boss.post(revoke, json::object()).status, 404);
  const std::string third = invitation();
  storage::Database(database(), false).execute("UPDATE invitations SET expires_at = 1 WHERE used_at IS NULL");  // days later
  EXPECT_EQ(client().sign_up(request("cid", third)).status, 403);
  EXPECT_EQ(accounts(), "ann,boss");
  expect_error(run({"admin", "revoke-invitation", "1"}), 1, "no open invitation 1 (unknown, used or revoked)");
  const json states = json::parse(run_ok({"admin", "invitations", "--json"}));
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states.at(0).at("state"), "used");
  EXPECT_EQ(states.at(1).at("state"), "revoked") << "revoked stays revoked once expired too";
  EXPECT_EQ(states.at(2).at("state"), "expired");
}

TEST_F(sign_up, GuessingCodesLocksTheAddressOut) {
  user_with_active_project("boss", "lab");
  start_server(app::SignUpPolicy::invite);
  const std::string code = invitation();
  int locked_after = 0;
  for (int i = 1; i <= 40 && locked_after == 0; ++i)
    if (client().sign_up(request("eve", "guess" + std::to_string(i))).status == 429) locked_after = i;
  EXPECT_GT(locked_after, 1);
  EXPECT_LE(locked_after, 21) << "the address is locked after 20 refusals, as for sign-ins";
  EXPECT_EQ(client().sign_up(request("eve", code)).status, 429) << "even the right code, while locked";
  EXPECT_EQ(accounts(), "boss");
}

}  // namespace
}  // namespace sd::test
