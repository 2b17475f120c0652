// SWARMDESIGN_WEB_ROOT (the build tree's web-root) is defined for this file alone, so that no
// other object of the program names a folder of one clone: ccache reuses them in any clone.
#include "cli/web_root.hpp"

#include <filesystem>
#include <system_error>

namespace sd::cli {

std::string default_web_root() {
  std::error_code error;
  const std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = binary.parent_path().parent_path() / "share" / "swarmdesign" / "web-root";
    if (std::filesystem::is_regular_file(installed / "index.html", error)) return installed.string();
  }
  return SWARMDESIGN_WEB_ROOT;
}

}  // namespace sd::cli
