#pragma once
// Stored times are Unix seconds (UTC).
#include <chrono>
#include <cstdint>
#include <string>

namespace sd::storage {

inline std::int64_t unix_now() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// "2024-05-01 14:03 UTC", for listings.
std::string format_time(std::int64_t unix_seconds);
/// "2024-05-01T14:03:09Z" (ISO 8601), for documents.
std::string format_iso_time(std::int64_t unix_seconds);

}  // namespace sd::storage
