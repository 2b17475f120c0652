#include "storage/session_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <system_error>

#include "core/durable_file.hpp"
#include "storage/errors.hpp"

namespace sd::storage {

namespace {
[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path) {
  throw std::system_error(errno, std::generic_category(), what + " " + path.string());
}

/// Closes the descriptor on every path out.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string mode_text(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
  return text;
}

bool is_token(const std::string& text) {
  return text.size() == 64 &&
         std::all_of(text.begin(), text.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}
}  // namespace

void write_session_file(const std::filesystem::path& path, const std::string& token) {
  replace_file_durably(path, token + "\n", 0600, Umask::Ignored);  // exactly private
}

std::optional<std::string> read_session_file(const std::filesystem::path& path) {
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC)};
  if (file.fd < 0) {
    if (errno == ENOENT) return std::nullopt;
    fail("cannot open session file", path);
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) fail("cannot inspect session file", path);
  if (!S_ISREG(status.st_mode) || status.st_uid != ::geteuid() || (status.st_mode & 077) != 0)
    throw AccessDenied("session file " + path.string() + " is not private to you (mode " + mode_text(status.st_mode) +
                       "); remove it and sign in again");
  char buffer[128];
  const ssize_t size = ::read(file.fd, buffer, sizeof buffer);
  if (size < 0) fail("cannot read session file", path);
  std::string token(buffer, static_cast<std::size_t>(size));
  while (!token.empty() && (token.back() == '\n' || token.back() == '\r')) token.pop_back();
  if (!is_token(token)) throw AccessDenied("session file " + path.string() + " is damaged; sign in again");
  return token;
}

void remove_session_file(const std::filesystem::path& path) {
  if (::unlink(path.c_str()) != 0 && errno != ENOENT) fail("cannot remove session file", path);
}

}  // namespace sd::storage
