#pragma once
// Reading a file a user named: opened once, and every check made on what was opened (no
// check-then-open race), so a symbolic link swapped in between cannot lead elsewhere. Only a
// regular file is read (a device such as /dev/zero or a FIFO would read or block without
// end), and only up to a bound, whatever its size said when it was opened.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

namespace sd {

/// No real input (a mission, a configuration string, a protocol, a weight document) comes
/// near this; a larger file is refused before a byte of it is read.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 20;

enum class FileProblem {
  Missing,     // no such file, or it cannot be opened
  Outside,     // opened, but it is not where the reader may read
  NotRegular,  // a folder, device, FIFO or socket
  TooLarge,    // more than the bound
  Unreadable,  // an error while reading
};

struct FileReadError : std::runtime_error {
  FileReadError(FileProblem p, const std::string& message) : std::runtime_error(message), problem(p) {}
  FileProblem problem;
};

struct FileText {
  std::filesystem::path real_path;  // what was opened, every link resolved
  std::string text;
};

/// Where a reader may read: true for a real path (no link, no "..") it may use.
using PathRule = std::function<bool(const std::filesystem::path& real_path)>;

/// The file's whole text. `allowed` (if given) is asked about the real path of the file that
/// was opened, before anything else is said about it; a reader so confined also refuses a file
/// with more than one name (a hard link may name a file from outside), as Outside. Throws
/// FileReadError whose message names `what` and the path as given, and never quotes the file.
FileText read_bounded_file(const std::filesystem::path& path, const std::string& what,
                           std::size_t max_bytes = kMaxInputFileBytes, const PathRule& allowed = {});

/// A file the program keeps in a folder of its own and reads by itself, never one a user names
/// (a design's assessment.json, its pseudo-reality.json): read as confined as a file a user
/// names, to that folder's own entry, so that a link planted at its name, symbolic (anywhere)
/// or hard (a second name of another account's file), is refused as Outside, never followed.
FileText read_folder_file(const std::filesystem::path& folder, const std::string& name, const std::string& what,
                          std::size_t max_bytes = kMaxInputFileBytes);

/// True when `path` is `folder` or lies below it (both real paths).
bool is_within(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace sd
