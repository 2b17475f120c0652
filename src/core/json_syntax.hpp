#pragma once
// A JSON syntax error said without quoting the document: nlohmann's own message ends with the
// last bytes it read ("last read: '...'"), which may be anything a file holds (a file the user
// should not see, a password pasted by mistake). This keeps the parser's words for what went
// wrong and says where, by line and column, and nothing of the text itself.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace sd {

/// "syntax error while parsing value - invalid literal (line 3, column 7)" for a parse_error
/// (anything with what() and byte, the 1-based position of the last byte read) of `text`.
template <class ParseError>
std::string json_syntax_error(const ParseError& error, std::string_view text) {
  const std::string_view message = error.what();
  std::size_t begin = message.find("column ");
  begin = begin == std::string_view::npos ? message.find("] ") : message.find(": ", begin);
  begin = begin == std::string_view::npos ? 0 : begin + 2;
  const std::size_t end = std::min(message.find("; last read", begin), message.size());
  std::string said(message.substr(begin, end - begin));
  const std::size_t at = std::min<std::size_t>(error.byte > 0 ? error.byte - 1 : 0, text.size());
  const std::string_view before = text.substr(0, at);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t last_newline = before.rfind('\n');
  const std::size_t column = 1 + (last_newline == std::string_view::npos ? at : at - last_newline - 1);
  return said + " (line " + std::to_string(line) + ", column " + std::to_string(column) + ")";
}

/// "number overflow parsing '1e999'": nlohmann reports a number too large for a double as
/// out_of_range (406) rather than parse_error, so every reader of user text catches both.
template <class OutOfRange>
std::string json_number_error(const OutOfRange& error) {
  const std::string_view message = error.what();
  const std::size_t begin = message.find("] ");
  return std::string(begin == std::string_view::npos ? message : message.substr(begin + 2));
}

}  // namespace sd
