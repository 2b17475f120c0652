#pragma once
// How a route is declared: every /api/ route but sign-in needs a session; every POST needs a
// JSON body and (but sign-in) the session's CSRF token; every error becomes {"error"} with its
// status. A route is a function of a Call, so each route file is only what the route does.
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/background_designs.hpp"
#include "app/background_experiments.hpp"
#include "app/cluster_collector.hpp"
#include "app/design_backends.hpp"
#include "app/home.hpp"
#include "app/sign_up.hpp"
#include "app/accounts.hpp"
#include "web/password_slots.hpp"
#include "web/run_registry.hpp"
#include "web/session_guard.hpp"
#include "web/sign_in_limiter.hpp"

namespace sd::web {

/// What the routes share for the server's lifetime.
struct WebContext {
  WebContext(std::filesystem::path home_folder, std::filesystem::path web_root_folder, storage::SignInPolicy policy,
             bool tls_proxy, app::SignUpPolicy sign_up_policy = app::SignUpPolicy::closed)
      : home(std::move(home_folder)), web_root(std::move(web_root_folder)), sign_in(policy), behind_tls(tls_proxy),
        sign_up(sign_up_policy),
        addresses(policy), passwords(kPasswordChecksAtOnce), designs("web"), experiments("webx"),
        cluster_experiments(home, kClusterCollectionInterval) {}
  static constexpr int kPasswordChecksAtOnce = 4;  // 256 MiB of Argon2id at most
  static constexpr std::chrono::seconds kClusterCollectionInterval{20};
  std::filesystem::path home;
  std::filesystem::path web_root;  // the built front end (the report page's bundle)
  storage::SignInPolicy sign_in;
  bool behind_tls;                 // session cookies only over HTTPS (a TLS proxy in front)
  app::SignUpPolicy sign_up;       // who may make an account on the page (app/sign_up.hpp)
  SignInLimiter addresses;         // failed sign-ins per client address
  PasswordSlots passwords;         // password checks at once (password_slots.hpp)
  SessionGuard guard;
  RunRegistry runs;
  app::BackgroundDesigns designs;
  app::BackgroundExperiments experiments;
  app::ClusterCollector cluster_experiments;  // the pages' reads only follow; it collects
};

/// One request being answered: its own connection to the home (SQLite connections are per
/// thread), the signed-in user, and the JSON body of a POST.
struct Call {
  const httplib::Request& request;
  httplib::Response& response;
  app::Home& home;
  storage::User user;
  nlohmann::json body;
  WebContext& context;

  /// The n-th group of the route's pattern.
  std::string match(std::size_t n) const { return request.matches[static_cast<int>(n)].str(); }
};

class Routes {
 public:
  using JsonRoute = std::function<nlohmann::json(Call&)>;
  using RawRoute = std::function<void(Call&)>;  // sets the response itself (SVG, event streams)

  Routes(httplib::Server& server, WebContext& context) : server_(server), context_(context) {}

  void get(const std::string& pattern, JsonRoute route);
  void get_raw(const std::string& pattern, RawRoute route);
  void post(const std::string& pattern, JsonRoute route);
  /// POST without a session (sign-in): still JSON only, so no cross-site form can send it.
  void post_public(const std::string& pattern, RawRoute route);
  /// GET without a session: what the sign-in page must know before anyone signs in.
  void get_public(const std::string& pattern, JsonRoute route);

  WebContext& context() { return context_; }

 private:
  // The handlers outlive this object (it only declares them): they hold the context, not it.
  static void answer(WebContext& context, const httplib::Request& request, httplib::Response& response, bool post,
                     bool session, const RawRoute& route);

  httplib::Server& server_;
  WebContext& context_;
};

/// A project name in a route pattern (storage/validation's rule for names).
inline constexpr const char* kNamePattern = "([A-Za-z][A-Za-z0-9._-]{0,63})";

/// A read that shows a running experiment asks the server's collector to follow its project: a
/// cluster project's designs come home on the collector's ticker, never inside a request.
void follow_running(Call& call, const std::string& project, const std::vector<app::ExperimentProgress>& experiments);

/// How much of a design a status read gives: everything (`status --complete`) unless the page
/// asks `?race_log=false`, its polls' way to leave the costly race log out.
app::StatusDetail status_detail(const httplib::Request& request);

void add_account_routes(Routes& routes);
void add_software_routes(Routes& routes);
void add_mission_routes(Routes& routes);
void add_run_routes(Routes& routes);
void add_project_routes(Routes& routes);
void add_experiment_routes(Routes& routes);
void add_design_form_routes(Routes& routes);
void add_admin_routes(Routes& routes);

}  // namespace sd::web
