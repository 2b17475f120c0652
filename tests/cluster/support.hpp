#pragma once
// What the cluster tests share: a temporary folder, an environment variable set for one test,
// and a stand-in for ssh that runs the "remote" command on this machine, so that the ssh code
// paths (one script argument, stdin, tar streams) run for real without an sshd.
#include <pwd.h>
#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "cluster/shell.hpp"

namespace sd::cluster::test_support {

namespace fs = std::filesystem;

struct TempFolder {
  fs::path path;
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "sd-cluster-XXXXXX").string();
    path = ::mkdtemp(pattern.data());
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

class ScopedEnv {
 public:
  ScopedEnv(std::string name, const std::string& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    ::setenv(name_.c_str(), value.c_str(), 1);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_.c_str(), old_->c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

inline void write_text(const fs::path& file, const std::string& content, bool executable = false) {
  std::ofstream(file, std::ios::binary) << content;
  if (executable) fs::permissions(file, fs::perms::owner_all, fs::perm_options::add);
}

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::string current_user() {
  const passwd* entry = ::getpwuid(::geteuid());
  return entry ? entry->pw_name : "";
}

/// A Shell that takes the ssh road to 127.0.0.1 with `folder`/fake-ssh as its ssh: it drops
/// the options and the destination and hands the rest, joined by spaces, to sh — what ssh
/// does with the remote login shell.
inline Shell fake_ssh_shell(const fs::path& folder) {
  const fs::path fake = folder / "fake-ssh";
  write_text(fake,
             "#!/bin/sh\n"
             "while [ \"$#\" -gt 0 ] && [ \"$1\" != \"--\" ]; do shift; done\n"
             "shift\n"
             "exec /bin/sh -c \"$*\"\n",
             true);
  const ScopedEnv ssh("SWARMDESIGN_SSH", fake.string());
  return Shell::for_cluster("127.0.0.1", current_user());
}

}  // namespace sd::cluster::test_support
