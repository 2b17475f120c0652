#pragma once
// The fields of one line of the plain comma-separated files SwarmDesign reads (ARGoS' reference
// scores and traces): no quoting, as those files have none, and a trailing '\r' dropped, as
// the first reference file has CRLF line ends.
#include <string_view>
#include <vector>

namespace sd {

/// The line's fields, views into `line`; "" gives one empty field, "a," two.
inline std::vector<std::string_view> csv_fields(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace sd
