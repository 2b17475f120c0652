#pragma once
// Replacing a small file so that a kill or a power cut leaves either the old content or the
// new one, never a mix or an empty file: write a private temporary beside it, fsync it,
// rename it over the file, and fsync the folder so that the rename itself is on disk.
// Used for the files a user cannot afford to lose outside SQLite (session token, EvoStick
// state).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace sd {

/// Replaces `path` with `content`, created with exactly `mode` (the umask does not apply).
/// Throws std::system_error naming the file on failure; the old file is then untouched.
inline void replace_file_durably(const std::filesystem::path& path, std::string_view content, mode_t mode) {
  const auto fail = [](const std::string& what, const std::filesystem::path& file) {
    throw std::system_error(errno, std::generic_category(), what + " " + file.string());
  };
  // The pid keeps two processes replacing one file from writing into the same temporary.
  const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, mode);
  if (fd < 0) fail("cannot create", temporary);
  std::size_t written = 0;
  bool ok = ::fchmod(fd, mode) == 0;
  while (ok && written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) written += static_cast<std::size_t>(n);
  }
  ok = ok && ::fsync(fd) == 0;
  const int write_error = errno;
  ::close(fd);
  if (ok && ::rename(temporary.c_str(), path.c_str()) == 0) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {  // best effort: some file systems cannot fsync a folder
      ::fsync(dir);
      ::close(dir);
    }
    return;
  }
  const int error = ok ? errno : write_error;
  ::unlink(temporary.c_str());
  errno = error;
  fail(ok ? "cannot replace" : "cannot write", ok ? path : temporary);
}

}  // namespace sd
