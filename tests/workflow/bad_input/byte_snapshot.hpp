#pragma once
// Every byte under a folder, to prove that a refused input wrote nothing: the SQLite database
// and its WAL, the session, the project and design folders, the files the cases named.
#include <filesystem>
#include <map>
#include <string>

namespace sd::test::bad_input {

/// Relative path -> content ("<dir>" for a folder). SQLite's "-shm" file is left out: it is
/// the WAL's shared-memory index, rewritten by every reader (read marks), and holds no data.
using ByteSnapshot = std::map<std::string, std::string>;

ByteSnapshot byte_snapshot(const std::filesystem::path& root);
/// The paths added, removed or changed from `before` to `after`, one per line ("" if none).
std::string differences(const ByteSnapshot& before, const ByteSnapshot& after);

}  // namespace sd::test::bad_input
