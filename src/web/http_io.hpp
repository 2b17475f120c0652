#pragma once
// The one way a route reads a request and answers: JSON bodies, JSON errors with the status
// of the application's error kind (src/app/README.md), and the HTTP-only refusals (401, 403,
// 413) that have no application kind.
#include <httplib.h>
#include <nlohmann/json_fwd.hpp>

#include <exception>
#include <stdexcept>
#include <string>

#include "app/errors.hpp"

namespace sd::web {

/// A refusal that only HTTP has a word for: no session (401), no CSRF token (403), ...
struct HttpError : std::runtime_error {
  HttpError(int code, const std::string& message) : std::runtime_error(message), status(code) {}
  int status;
};

int http_status(app::ErrorKind kind);

/// The body as a JSON object; InvalidRequest naming what is wrong with it.
nlohmann::json read_json_body(const httplib::Request& request);

/// A field of a JSON body as text (a whole number is taken as its digits: seeds, budgets);
/// InvalidRequest naming the field when it is missing or of another type.
std::string text_field(const nlohmann::json& body, const char* key);
/// The field's name in `body`: `key`, or `old_key` when only that is there (a renamed field's
/// first spelling, accepted for one release).
const char* alias_or(const nlohmann::json& body, const char* key, const char* old_key);

/// A yes/no query parameter (`?race_log=false`): "true"/"1" or "false"/"0", `fallback` when
/// absent; InvalidRequest naming it otherwise.
bool query_flag(const httplib::Request& request, const char* key, bool fallback);

void send_json(httplib::Response& response, const nlohmann::json& body, int status = 200);
/// `text` with every path under the server's home made relative to it (users/NAME/projects/...):
/// a web user never sees where on the server's disk the home is (issue #56).
std::string without_server_paths(std::string text, const std::string& home);
/// {"error": "..."} with the status of the exception's kind; a failure of the server itself
/// says only that it failed (the details go to the server's log).
void send_error(httplib::Response& response, const std::exception& error, const std::string& home = {});

}  // namespace sd::web
