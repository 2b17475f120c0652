#include "core/home.hpp"

#include <pwd.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace sd {

namespace {
std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

std::filesystem::path user_home_directory() {
  if (auto home = environment("HOME"); !home.empty()) return home;
  // getpwuid_r: threads may ask at once (getpwuid shares one buffer).
  passwd entry{};
  passwd* found = nullptr;
  char buffer[4096];
  if (getpwuid_r(getuid(), &entry, buffer, sizeof buffer, &found) == 0 && found && found->pw_dir) return found->pw_dir;
  throw std::runtime_error("cannot find your home directory; set SWARMDESIGN_HOME");
}
}  // namespace

std::filesystem::path swarmdesign_home() {
  if (auto home = environment("SWARMDESIGN_HOME"); !home.empty())
    return std::filesystem::absolute(home).lexically_normal();
  if (std::filesystem::path xdg = environment("XDG_DATA_HOME"); xdg.is_absolute())
    return (xdg / "swarmdesign").lexically_normal();
  return (user_home_directory() / ".local" / "share" / "swarmdesign").lexically_normal();
}

}  // namespace sd
