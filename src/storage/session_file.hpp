#pragma once
// The file that holds a signed-in user's session token: created with mode 0600 and
// replaced atomically; a token file that others could read is refused, as ssh refuses a
// private key that is open to others.
#include <filesystem>
#include <optional>
#include <string>

namespace sd::storage {

void write_session_file(const std::filesystem::path& path, const std::string& token);

/// The token, or nullopt when there is no file. AccessDenied when the file is not private
/// to this user or is damaged.
std::optional<std::string> read_session_file(const std::filesystem::path& path);

void remove_session_file(const std::filesystem::path& path);

}  // namespace sd::storage
