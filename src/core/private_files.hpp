#pragma once
// Folders and files only their owner can read, whatever umask the process was started with.
// The home holds password hashes, session tokens and every user's designs: the CLI and the
// server create its folders 0700 and its databases 0600 alike, so the home's modes never
// depend on which front end wrote a file (the server also sets umask 077 for the rest).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>

namespace sd {

/// Creates `folder` and every missing folder above it with mode 0700; folders that exist keep
/// their mode. Throws std::system_error naming the folder it could not make.
inline void create_private_folders(const std::filesystem::path& folder) {
  std::filesystem::path made;
  for (const auto& part : folder) {
    made /= part;
    if (::mkdir(made.c_str(), 0700) == 0) {
      ::chmod(made.c_str(), 0700);  // exactly private: a umask like 0277 would take the owner's bits
    } else if (errno != EEXIST) {
      throw std::system_error(errno, std::generic_category(), "cannot create folder " + made.string());
    }
  }
}

/// Creates an empty `path` with mode 0600 if nothing is there yet (an empty file is a valid
/// empty SQLite database, which then keeps that mode, its -wal and -shm files too). A link
/// planted at the name is not followed.
inline void create_private_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) {
    if (errno == EEXIST) return;  // another process was first, or it is there already
    throw std::system_error(errno, std::generic_category(), "cannot create " + path.string());
  }
  ::fchmod(fd, 0600);
  ::close(fd);
}

}  // namespace sd
