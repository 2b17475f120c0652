#include "workflow/bad_input/byte_snapshot.hpp"

#include <fstream>
#include <sstream>
#include <utility>

namespace sd::test::bad_input {

ByteSnapshot byte_snapshot(const std::filesystem::path& root) {
  ByteSnapshot snapshot;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 4 && name.compare(name.size() - 4, 4, "-shm") == 0) continue;
    const std::string relative = std::filesystem::relative(entry.path(), root).string();
    if (entry.is_directory()) {
      snapshot[relative] = "<dir>";
    } else if (entry.is_regular_file()) {
      // Copied by the stream buffer, not character by character: the snapshot is taken after
      // each of hundreds of cases, of a folder that holds a 2 MiB mission.
      std::ifstream file(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << file.rdbuf();
      snapshot[relative] = std::move(bytes).str();
    } else {
      snapshot[relative] = "<special>";  // the FIFO a case names
    }
  }
  return snapshot;
}

std::string differences(const ByteSnapshot& before, const ByteSnapshot& after) {
  std::string text;
  for (const auto& [path, bytes] : before) {
    const auto found = after.find(path);
    if (found == after.end()) text += "removed " + path + "\n";
    else if (found->second != bytes) text += "changed " + path + "\n";
  }
  for (const auto& [path, bytes] : after)
    if (!before.count(path)) text += "added " + path + "\n";
  return text;
}

}  // namespace sd::test::bad_input
