#include "web/routes.hpp"

#include "web/http_io.hpp"

namespace sd::web {

namespace {

/// 200 unless the route chose another status (a parse error answered with its token).
void answer_json(Call& call, const nlohmann::json& body) {
  send_json(call.response, body, call.response.status > 0 ? call.response.status : 200);
}

}  // namespace

void Routes::answer(WebContext& context, const httplib::Request& request, httplib::Response& response, bool post,
                    bool session, const RawRoute& route) {
  try {
    if (post && request.get_header_value("Content-Type").rfind("application/json", 0) != 0)
      throw HttpError(415, "send the request body as application/json");
    app::Home home(context.home);
    storage::User user = session ? context.guard.require_user(request, home) : storage::User{};
    if (session && post) context.guard.require_csrf(request);
    nlohmann::json body = post ? read_json_body(request) : nlohmann::json::object();
    Call call{request, response, home, std::move(user), std::move(body), context};
    route(call);
  } catch (const std::exception& e) {
    send_error(response, e, context.home.string());
  }
}

void Routes::get(const std::string& pattern, JsonRoute route) {
  server_.Get(pattern, [context = &context_, route](const httplib::Request& q, httplib::Response& r) {
    answer(*context, q, r, false, true, [&route](Call& call) { answer_json(call, route(call)); });
  });
}

void Routes::get_raw(const std::string& pattern, RawRoute route) {
  server_.Get(pattern, [context = &context_, route = std::move(route)](const httplib::Request& q, httplib::Response& r) { answer(*context, q, r, false, true, route); });
}

void Routes::post(const std::string& pattern, JsonRoute route) {
  server_.Post(pattern, [context = &context_, route](const httplib::Request& q, httplib::Response& r) {
    answer(*context, q, r, true, true, [&route](Call& call) { answer_json(call, route(call)); });
  });
}

void Routes::post_public(const std::string& pattern, RawRoute route) {
  server_.Post(pattern, [context = &context_, route = std::move(route)](const httplib::Request& q, httplib::Response& r) { answer(*context, q, r, true, false, route); });
}

void Routes::get_public(const std::string& pattern, JsonRoute route) {
  server_.Get(pattern, [context = &context_, route](const httplib::Request& q, httplib::Response& r) {
    answer(*context, q, r, false, false, [&route](Call& call) { answer_json(call, route(call)); });
  });
}

void follow_running(Call& call, const std::string& project, const std::vector<app::ExperimentProgress>& experiments) {
  for (const auto& e : experiments)
    if (e.experiment.state == storage::DesignState::running && !call.context.experiments.running_here(e.experiment.id)) {
      call.context.cluster_experiments.follow(call.user, project);
      return;
    }
}

app::StatusDetail status_detail(const httplib::Request& request) {
  return query_flag(request, "race_log", true) ? app::StatusDetail::complete : app::StatusDetail::convergence;
}

}  // namespace sd::web
