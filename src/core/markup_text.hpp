#pragma once
// Text from a user or a file placed in HTML or SVG as character data: "<script>" in a mission
// title or a report title stays text.
#include <string>
#include <string_view>

namespace sd {

inline std::string markup_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace sd
