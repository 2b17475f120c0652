#include "web/http_io.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

#include "app/quotas.hpp"
#include "core/json_syntax.hpp"

namespace sd::web {

int http_status(app::ErrorKind kind) {
  switch (kind) {
    case app::ErrorKind::InvalidRequest: return 400;
    case app::ErrorKind::NotFound: return 404;
    case app::ErrorKind::Conflict: return 409;
    case app::ErrorKind::AccessDenied: return 403;
    case app::ErrorKind::Refused: return 409;
    case app::ErrorKind::TooManyAttempts: return 429;
    case app::ErrorKind::Failed: return 500;
  }
  return 500;
}

nlohmann::json read_json_body(const httplib::Request& request) {
  nlohmann::json body;
  static const std::string kEmptyObject = "{}";
  const std::string& text = request.body.empty() ? kEmptyObject : request.body;
  try {
    body = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw app::InvalidRequest("the request body is not JSON: " + json_syntax_error(e, text));
  } catch (const nlohmann::json::out_of_range& e) {
    throw app::InvalidRequest("the request body is not JSON: " + json_number_error(e));
  }
  if (!body.is_object()) throw app::InvalidRequest("the request body must be a JSON object");
  return body;
}

std::string text_field(const nlohmann::json& body, const char* key) {
  if (!body.contains(key) || body.at(key).is_null()) throw app::InvalidRequest(std::string(key) + " is missing");
  const nlohmann::json& value = body.at(key);
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return value.dump();
  throw app::InvalidRequest(std::string(key) + " must be text or a whole number");
}

bool query_flag(const httplib::Request& request, const char* key, bool fallback) {
  if (!request.has_param(key)) return fallback;
  const std::string value = request.get_param_value(key);
  if (value == "true" || value == "1") return true;
  if (value == "false" || value == "0") return false;
  throw app::InvalidRequest(std::string(key) + " must be true or false, not '" + value.substr(0, 40) + "'");
}

void send_json(httplib::Response& response, const nlohmann::json& body, int status) {
  response.status = status;
  // Replace bad UTF-8 rather than throw: a name from a file must not take the answer down.
  response.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

std::string without_server_paths(std::string text, const std::string& home) {
  if (home.empty()) return text;
  const std::string root = home.back() == '/' ? home : home + "/";
  for (std::size_t at = text.find(root); at != std::string::npos; at = text.find(root, at)) text.erase(at, root.size());
  return text;
}

void send_error(httplib::Response& response, const std::exception& error, const std::string& home) {
  if (const auto* http = dynamic_cast<const HttpError*>(&error)) {
    send_json(response, {{"error", without_server_paths(http->what(), home)}}, http->status);
    return;
  }
  if (const auto* wait = dynamic_cast<const storage::TooManyAttempts*>(&error))
    response.set_header("Retry-After", std::to_string(wait->retry_after));
  const app::ErrorKind kind = app::classify(error);
  if (kind == app::ErrorKind::Failed) {
    std::cerr << "run-exp: request failed: " << error.what() << "\n";  // the log keeps every path
    send_json(response, {{"error", "the server failed: " + without_server_paths(error.what(), home)}}, 500);
    return;
  }
  nlohmann::json body{{"error", without_server_paths(error.what(), home)}};
  if (const auto* quota = dynamic_cast<const app::QuotaExceeded*>(&error)) body["quota"] = quota->quota;
  send_json(response, body, http_status(kind));
}

const char* alias_or(const nlohmann::json& body, const char* key, const char* old_key) {
  return !body.contains(key) && body.contains(old_key) ? old_key : key;
}

}  // namespace sd::web
