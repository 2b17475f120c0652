#include "cluster/transfer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

namespace sd::cluster {

namespace fs = std::filesystem;

namespace {

// The exit status our read command gives for "no such file", told apart from cat failing.
constexpr int absent_status = 44;

std::string parent_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos || slash == 0 ? std::string{} : path.substr(0, slash);
}

std::string reason(const CommandResult& result) {
  const std::string line = first_line(result.err);
  return line.empty() ? "exit code " + std::to_string(result.exit_code) : line;
}

[[noreturn]] void fail(const std::string& what, const std::string& path, const Shell& shell, const std::string& why) {
  throw ClusterError("cannot " + what + " " + path + " on " + shell.describe() + ": " + why);
}

// A temporary file here that is removed however we leave.
class TemporaryFile {
 public:
  TemporaryFile() {
    std::string pattern = (fs::temp_directory_path() / "swarmdesign-fetch-XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw ClusterError("cannot create a temporary file in " + fs::temp_directory_path().string() + ": " + std::generic_category().message(errno));
    ::close(fd);
    path_ = pattern;
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_here(const Shell& shell, const std::string& path, const std::string& content, bool executable) {
  const fs::path file = local_path(path);
  std::error_code error;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), error);
  if (error) fail("write", path, shell, error.message());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) fail("write", path, shell, std::generic_category().message(errno));
  if (executable) {
    fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add, error);
    if (error) fail("make executable", path, shell, error.message());
  }
}

std::optional<std::string> read_here(const Shell& shell, const std::string& path, std::size_t max_bytes) {
  const fs::path file = local_path(path);
  std::error_code error;
  if (!fs::exists(file, error)) {
    if (error) fail("read", path, shell, error.message());
    return std::nullopt;
  }
  if (fs::is_directory(file, error)) fail("read", path, shell, "it is a folder");
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) fail("read", path, shell, std::generic_category().message(errno));
  const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
  const std::size_t start = size > max_bytes ? size - max_bytes : 0;
  in.seekg(static_cast<std::streamoff>(start));
  std::string content(size - start, '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));  // it may have shrunk since
  if (in.bad()) fail("read", path, shell, std::generic_category().message(errno));
  return content;
}

void fetch_here(const Shell& shell, const std::string& remote_folder, const fs::path& local_folder) {
  const fs::path from = local_path(remote_folder);
  std::error_code error;
  if (!fs::is_directory(from, error)) fail("fetch folder", remote_folder, shell, "it is not a folder");
  fs::create_directories(local_folder, error);
  if (!error && fs::equivalent(from, local_folder, error)) return;  // already there
  if (!error) fs::copy(from, local_folder, fs::copy_options::recursive | fs::copy_options::overwrite_existing, error);
  if (error) fail("fetch folder", remote_folder, shell, error.message());
}

void fetch_over_ssh(const Shell& shell, const std::string& remote_folder, const fs::path& local_folder, int timeout_s) {
  const TemporaryFile archive;
  CommandOptions options;
  options.timeout_s = timeout_s;
  options.stdout_file = archive.path();
  const CommandResult packed = shell.run_checked_with("tar -C " + shell_path(remote_folder) + " -cf - .", options);
  if (packed.exit_code != 0) fail("fetch folder", remote_folder, shell, reason(packed));
  std::error_code error;
  fs::create_directories(local_folder, error);
  if (error) throw ClusterError("cannot create " + local_folder.string() + ": " + error.message());
  // --no-same-owner: as root, tar would otherwise give the files the cluster's user ids.
  const CommandResult unpacked = run_command(
      {"tar", "-C", local_folder.string(), "--no-same-owner", "-xf", archive.path().string()}, "", timeout_s);
  if (unpacked.exit_code != 0 || !unpacked.started())
    throw ClusterError("cannot unpack " + remote_folder + " from " + shell.describe() + " into " + local_folder.string() +
                       ": " + reason(unpacked));
}

}  // namespace

fs::path local_path(std::string_view path) {
  if (path != "~" && path.rfind("~/", 0) != 0) return fs::path(path);
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw ClusterError("cannot expand " + std::string(path) + ": HOME is not set");
  return path == "~" ? fs::path(home) : fs::path(home) / path.substr(2);
}

void write_file(const Shell& shell, const std::string& path, const std::string& content, bool executable) {
  if (shell.local()) return write_here(shell, path, content, executable);
  const std::string part = path + ".swarmdesign-part";
  std::string script;
  if (const std::string parent = parent_of(path); !parent.empty()) script += "mkdir -p " + shell_path(parent) + " && ";
  script += "cat > " + shell_path(part);
  if (executable) script += " && chmod +x " + shell_path(part);
  script += " && mv -f " + shell_path(part) + " " + shell_path(path);
  const CommandResult result = shell.run_checked(script, content);
  if (result.exit_code != 0) fail("write", path, shell, reason(result));
}

std::optional<std::string> read_file(const Shell& shell, const std::string& path, std::size_t max_bytes) {
  if (shell.local()) return read_here(shell, path, max_bytes);
  const std::string quoted = shell_path(path);
  // A folder is refused as here: tail would say so in its own words, or read nothing.
  const CommandResult result = shell.run_checked(
      "if [ -d " + quoted + " ]; then echo 'it is a folder' >&2; exit 1; elif [ -e " + quoted + " ]; then exec tail -c " +
      std::to_string(max_bytes) + " " + quoted + "; else exit " + std::to_string(absent_status) + "; fi");
  if (result.exit_code == absent_status) return std::nullopt;
  if (result.exit_code != 0) fail("read", path, shell, reason(result));
  return result.out;
}

bool exists(const Shell& shell, const std::string& path) {
  if (shell.local()) {
    std::error_code error;
    const bool found = fs::exists(local_path(path), error);
    if (error) fail("look for", path, shell, error.message());
    return found;
  }
  const CommandResult result = shell.run_checked("if [ -e " + shell_path(path) + " ]; then echo yes; else echo no; fi");
  const std::string answer = first_line(result.out);
  if (result.exit_code != 0 || (answer != "yes" && answer != "no")) fail("look for", path, shell, reason(result));
  return answer == "yes";
}

void fetch_folder(const Shell& shell, const std::string& remote_folder, const fs::path& local_folder, int timeout_s) {
  if (shell.local()) return fetch_here(shell, remote_folder, local_folder);
  fetch_over_ssh(shell, remote_folder, local_folder, timeout_s);
}

}  // namespace sd::cluster
