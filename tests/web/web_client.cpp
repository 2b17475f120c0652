#include "web/web_client.hpp"

#include <chrono>
#include <stdexcept>

namespace sd::test {

namespace {

Answer answer_of(const httplib::Result& result) {
  if (!result) throw std::runtime_error("no answer from the server: " + httplib::to_string(result.error()));
  Answer a{result->status, nullptr, result->body, result->headers};
  a.body = nlohmann::json::parse(result->body, nullptr, false);
  if (a.body.is_discarded()) a.body = nullptr;
  return a;
}

}  // namespace

RunningServer::RunningServer(const std::filesystem::path& home, const std::filesystem::path& web_root)
    : RunningServer(web::WebServerOptions{"127.0.0.1", 0, web_root, home, {}, {}, false}) {}

RunningServer::RunningServer(web::WebServerOptions options) {
  options.host = "127.0.0.1";
  options.port = 0;
  server_ = std::make_unique<web::WebServer>(std::move(options));
  port_ = server_->bind();
  thread_ = std::thread([this] { server_->serve(); });
}

RunningServer::~RunningServer() {
  server_->stop();
  thread_.join();
}

WebClient::WebClient(int port) : client_("127.0.0.1", port) {
  client_.set_read_timeout(std::chrono::seconds(60));
  client_.set_connection_timeout(std::chrono::seconds(5));
}

bool WebClient::sign_in(const std::string& name, const std::string& password) {
  const auto result = client_.Post("/api/sign-in", nlohmann::json{{"name", name}, {"password", password}}.dump(),
                                   "application/json");
  if (!result || result->status != 200) {
    last_refusal_ = result ? std::to_string(result->status) + " " + result->body : httplib::to_string(result.error());
    return false;
  }
  const std::string set_cookie = result->get_header_value("Set-Cookie");
  cookie_ = set_cookie.substr(0, set_cookie.find(';'));
  csrf_ = nlohmann::json::parse(result->body).at("csrf").get<std::string>();
  return true;
}

Answer WebClient::sign_up(const nlohmann::json& body) {
  Answer answer = answer_of(client_.Post("/api/sign-up", body.dump(), "application/json"));
  if (answer.status == 200) {
    const std::string set_cookie = answer.headers.find("Set-Cookie") != answer.headers.end()
                                       ? answer.headers.find("Set-Cookie")->second
                                       : std::string();
    cookie_ = set_cookie.substr(0, set_cookie.find(';'));
    csrf_ = answer.body.at("csrf").get<std::string>();
  }
  return answer;
}

httplib::Headers WebClient::headers(bool csrf) const {
  httplib::Headers h;
  if (!cookie_.empty()) h.emplace("Cookie", cookie_);
  if (csrf && !csrf_.empty()) h.emplace("X-CSRF-Token", csrf_);
  return h;
}

Answer WebClient::get(const std::string& path) { return answer_of(client_.Get(path.c_str(), headers(false))); }

Answer WebClient::post(const std::string& path, const nlohmann::json& body, bool csrf) {
  return answer_of(client_.Post(path.c_str(), headers(csrf), body.dump(), "application/json"));
}

Answer WebClient::stream(const std::string& path) { return answer_of(client_.Get(path.c_str(), headers(false))); }

}  // namespace sd::test
