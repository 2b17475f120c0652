#pragma once
// Files on the cluster side, through a Shell: std::filesystem on this machine, sh commands
// over ssh (content on stdin, a tar stream back). A leading "~/" in a path means the home
// folder of the machine where the file is (see shell_path).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cluster/error.hpp"
#include "cluster/shell.hpp"

namespace sd::cluster {

/// Writes `content` (any bytes) to `path`, creating its parent folders; `executable` adds
/// the execute bits. Over ssh the file is written beside and renamed, so a reader never sees
/// half of it. ClusterError naming the path and the shell on failure.
void write_file(const Shell& shell, const std::string& path, const std::string& content, bool executable = false);

/// The content of `path`, or only its last `max_bytes` bytes when it is longer (a job's log may
/// hold a whole design's progress: a read is bounded, and the end is what is said); nullopt when
/// it does not exist; ClusterError when it cannot be read.
std::optional<std::string> read_file(const Shell& shell, const std::string& path, std::size_t max_bytes);

bool exists(const Shell& shell, const std::string& path);

/// Copies the content of `remote_folder` into `local_folder` (created), replacing files of
/// the same name and keeping the others. Over ssh: `tar -cf -` there, the stream saved to a
/// temporary file here, then `tar -xf` here (binary-safe, not held in memory).
void fetch_folder(const Shell& shell, const std::string& remote_folder, const std::filesystem::path& local_folder,
                  int timeout_s = 600);

/// `path` on this machine, with a leading "~/" (or a lone "~") replaced by $HOME.
std::filesystem::path local_path(std::string_view path);

}  // namespace sd::cluster
