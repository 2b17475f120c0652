// replace_file_durably: the new content with exactly the asked mode, no temporary left
// behind, and on failure the old file as it was.
#include "core/durable_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

namespace sd {
namespace {

namespace fs = std::filesystem;

struct TempFolder {
  fs::path path;
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "sd-durable-XXXXXX").string();
    path = ::mkdtemp(pattern.data());
  }
  ~TempFolder() { fs::remove_all(path); }
};

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

mode_t mode_of(const fs::path& file) {
  struct stat st {};
  ::stat(file.c_str(), &st);
  return st.st_mode & 07777;
}

TEST(DurableFile, ReplacesTheContentAndLeavesNoTemporary) {
  TempFolder folder;
  const fs::path file = folder.path / "state.json";
  replace_file_durably(file, "first\n", 0644);
  EXPECT_EQ(read(file), "first\n");
  replace_file_durably(file, "second, longer\n", 0644);
  EXPECT_EQ(read(file), "second, longer\n");
  replace_file_durably(file, "", 0644);
  EXPECT_EQ(read(file), "");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path), fs::directory_iterator()), 1);
}

TEST(DurableFile, GivesExactlyTheAskedModeUnlessTheUmaskApplies) {
  TempFolder folder;
  const mode_t old = ::umask(0277);
  replace_file_durably(folder.path / "token", "secret\n", 0600);
  replace_file_durably(folder.path / "shared", "open\n", 0644);
  replace_file_durably(folder.path / "user", "data\n", 0666, Umask::Applies);
  ::umask(old);
  EXPECT_EQ(mode_of(folder.path / "token"), 0600u);
  EXPECT_EQ(mode_of(folder.path / "shared"), 0644u);
  EXPECT_EQ(mode_of(folder.path / "user"), 0400u);  // 0666 without the umask's 0277
  EXPECT_EQ(read(folder.path / "token"), "secret\n");
}

TEST(DurableFile, AFailedReplacementLeavesTheOldFileAndNoTemporary) {
  TempFolder folder;
  // A folder in the file's place: the rename fails after the temporary was written.
  const fs::path occupied = folder.path / "occupied";
  fs::create_directories(occupied / "inside");
  try {
    replace_file_durably(occupied, "new\n", 0644);
    FAIL() << "replacing a folder succeeded";
  } catch (const std::system_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot replace " + occupied.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(occupied / "inside"));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path), fs::directory_iterator()), 1);
  // A missing folder: nothing can be created.
  EXPECT_THROW(replace_file_durably(folder.path / "missing" / "file", "x", 0644), std::system_error);
}

}  // namespace
}  // namespace sd
