#include "core/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <system_error>
#include <cerrno>
#include <cstring>

namespace sd {

namespace {

/// Closes the descriptor however the read ends.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string human_bytes(std::size_t bytes) {
  if (bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes % (std::size_t{1} << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

/// The real path of an open descriptor, as the kernel resolved it.
std::filesystem::path opened_path(int fd) {
  std::error_code ec;
  auto real = std::filesystem::read_symlink("/proc/self/fd/" + std::to_string(fd), ec);
  return ec ? std::filesystem::path() : real;
}

}  // namespace

bool is_within(const std::filesystem::path& path, const std::filesystem::path& folder) {
  if (folder.empty() || path.empty()) return false;
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty() && std::next(f) == folder.end()) break;  // "a/b/" ends with an empty part
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

FileText read_bounded_file(const std::filesystem::path& path, const std::string& what, std::size_t max_bytes,
                           const PathRule& allowed) {
  const std::string named = what + " " + path.string();
  // O_NONBLOCK: opening a FIFO must not wait for a writer; O_NOCTTY: a terminal never
  // becomes ours. Neither changes how a regular file reads.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) {
    const int error = errno;
    if (allowed) throw FileReadError(FileProblem::Missing, named + ": no such file");
    throw FileReadError(FileProblem::Missing, "cannot read " + named + ": " + std::generic_category().message(error));
  }
  FileText result{opened_path(file.fd), {}};
  if (allowed && (result.real_path.empty() || !allowed(result.real_path)))
    throw FileReadError(FileProblem::Outside, named + ": not a file you may read");
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) throw FileReadError(FileProblem::Unreadable, "cannot read " + named);
  // A hard link has no "real path" elsewhere: a second name for another user's file, planted in
  // one's own folder, resolves inside it. A confined reader therefore reads only files with one
  // name; SwarmDesign never makes a second one.
  if (allowed && S_ISREG(info.st_mode) && info.st_nlink > 1)
    throw FileReadError(FileProblem::Outside, named + ": not a file you may read");
  if (!S_ISREG(info.st_mode)) throw FileReadError(FileProblem::NotRegular, named + " is not a regular file");
  const auto too_large = [&] {
    return FileReadError(FileProblem::TooLarge, named + " is larger than " + human_bytes(max_bytes) +
                                                    ", more than any " + what + " needs");
  };
  if (static_cast<std::size_t>(info.st_size) > max_bytes) throw too_large();
  // Read up to one byte past the bound: a file that grew since fstat is refused as well.
  result.text.reserve(static_cast<std::size_t>(info.st_size));
  std::array<char, 65536> chunk{};
  for (;;) {
    const ssize_t n = ::read(file.fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileReadError(FileProblem::Unreadable, "cannot read " + named + ": " + std::generic_category().message(errno));
    if (n == 0) break;
    result.text.append(chunk.data(), static_cast<std::size_t>(n));
    if (result.text.size() > max_bytes) throw too_large();
  }
  return result;
}

FileText read_folder_file(const std::filesystem::path& folder, const std::string& name, const std::string& what,
                          std::size_t max_bytes) {
  // The folder's own path may go through links (a home under /data -> /mnt/...): it is resolved
  // first, and the file must then be its direct entry of that name.
  std::error_code error;
  const std::filesystem::path real_folder = std::filesystem::canonical(folder, error);
  const auto own_entry = [&](const std::filesystem::path& real) {
    return !error && real.parent_path() == real_folder && real.filename() == name;
  };
  return read_bounded_file(folder / name, what, max_bytes, own_entry);
}

}  // namespace sd
