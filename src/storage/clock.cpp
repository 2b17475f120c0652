#include "storage/clock.hpp"

#include <ctime>

namespace sd::storage {

namespace {
std::string utc_text(std::int64_t unix_seconds, const char* format) {
  const std::time_t time = static_cast<std::time_t>(unix_seconds);
  std::tm utc{};
  gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof text, format, &utc);
  return text;
}
}  // namespace

std::string format_time(std::int64_t unix_seconds) { return utc_text(unix_seconds, "%Y-%m-%d %H:%M UTC"); }
std::string format_iso_time(std::int64_t unix_seconds) { return utc_text(unix_seconds, "%Y-%m-%dT%H:%M:%SZ"); }

}  // namespace sd::storage
