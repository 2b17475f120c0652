#include "storage/validation.hpp"

#include <algorithm>
#include <charconv>

namespace sd::storage {

namespace {
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }  // ASCII only
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_char(char c) { return is_letter(c) || is_digit(c) || c == '.' || c == '_' || c == '-'; }

// Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "'" + std::string + "'".
std::string in_quotes(std::string_view value) {
  std::string text(1, '\'');
  text.append(value).push_back('\'');
  return text;
}
}  // namespace

std::string user_name_problem(std::string_view name) {
  if (name.empty()) return "user name is empty";
  if (name.size() > 32) return "user name " + in_quotes(name) + " is longer than 32 characters";
  if (!is_letter(name.front()) || !std::all_of(name.begin(), name.end(), is_name_char))
    return "user name " + in_quotes(name) +
           " is not valid: use a letter, then letters, digits, '.', '_' or '-'";
  return {};
}

std::string project_name_problem(std::string_view name) {
  if (name.empty()) return "project name is empty";
  if (name.size() > 64) return "project name " + in_quotes(name) + " is longer than 64 characters";
  const bool starts_well = is_letter(name.front()) || is_digit(name.front());
  if (!starts_well || !std::all_of(name.begin(), name.end(), is_name_char))
    return "project name " + in_quotes(name) +
           " is not valid: use a letter or digit, then letters, digits, '.', '_' or '-' (no '/' or spaces)";
  return {};
}

std::string host_problem(std::string_view host) {
  if (host.empty()) return "cluster host is empty";
  if (host.size() > 253) return "cluster host is longer than 253 characters";
  const bool valid = (is_letter(host.front()) || is_digit(host.front())) &&
                     std::all_of(host.begin(), host.end(), [](char c) { return is_letter(c) || is_digit(c) || c == '.' || c == '-'; });
  if (!valid) return "cluster host " + in_quotes(host) + " is not a host name or IPv4 address";
  return {};
}

std::string cluster_user_problem(std::string_view user) {
  if (user.empty()) return "cluster user is empty";
  if (user.size() > 64) return "cluster user is longer than 64 characters";
  if (user.front() == '-' || !std::all_of(user.begin(), user.end(), is_name_char))
    return "cluster user " + in_quotes(user) + " is not valid: use letters, digits, '.', '_' or '-'";
  return {};
}

std::string cluster_path_problem(std::string_view what, std::string_view path) {
  if (path.empty()) return {};
  if (path.size() > 1024) return std::string(what) + " is longer than 1024 characters";
  const bool plain = std::all_of(path.begin(), path.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f && c != '\'' && c != '"' && c != '$' && c != '`' && c != '\\';
  });
  if (!plain || path.front() == '-')
    return std::string(what) + " " + in_quotes(path) +
           " is not valid: no quotes, '$', '`', backslashes or control characters, and no leading '-'";
  return {};
}

std::optional<std::int64_t> parse_positive_integer(std::string_view text) {
  if (text.empty() || !std::all_of(text.begin(), text.end(), is_digit)) return std::nullopt;
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1) return std::nullopt;
  return value;
}

}  // namespace sd::storage
