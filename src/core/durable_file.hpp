#pragma once
// Replacing a small file so that a kill or a power cut leaves either the old content or the
// new one, never a mix or an empty file: write a temporary beside it, fsync it, rename it
// over the file, and fsync the folder so that the rename itself is on disk.
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

/// Whether the process' umask narrows the mode of a replaced file. A private file (a session
/// token) wants exactly its mode: a stray umask must not even take its owner's read bit.
enum class Umask { Applies, Ignored };

/// Replaces `path` with `content`, created with `mode` (narrowed by the umask if it applies).
/// Throws std::system_error naming the file on failure; the old file is then untouched and
/// no temporary is left.
inline void replace_file_durably(const std::filesystem::path& path, std::string_view content, mode_t mode,
                                 Umask umask = Umask::Ignored) {
  // The pid keeps two processes replacing one file from writing into the same temporary.
  const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
  const auto fail = [&](const std::string& what, const std::filesystem::path& file) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw std::system_error(error, std::generic_category(), what + " " + file.string());
  };
  // A fresh file, never one found at that name: a leftover of a killed save, or a link someone
  // planted there, is removed, and O_EXCL refuses anything that appears in between.
  ::unlink(temporary.c_str());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
  if (fd < 0) fail("cannot create", temporary);
  bool ok = umask == Umask::Applies || ::fchmod(fd, mode) == 0;
  for (std::size_t written = 0; ok && written < content.size();) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    written += ok ? static_cast<std::size_t>(n) : 0;
  }
  ok = ok && ::fsync(fd) == 0;
  const int write_error = errno;  // close must not hide why writing failed
  ::close(fd);
  errno = write_error;
  if (!ok) fail("cannot write", temporary);
  if (::rename(temporary.c_str(), path.c_str()) != 0) fail("cannot replace", path);
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {  // best effort: some file systems cannot fsync a folder
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace sd
