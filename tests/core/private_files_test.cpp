// create_private_folders / create_private_file: the home's folders 0700 and databases 0600
// whatever the umask, nothing existing changed, and no planted link followed.
#include "core/private_files.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "core/durable_file.hpp"

namespace sd {
namespace {

namespace fs = std::filesystem;

struct TempFolder {
  fs::path path;
  mode_t umask_before;
  TempFolder() : umask_before(::umask(022)) {  // a usual umask: 0755 folders, 0644 files
    std::string pattern = (fs::temp_directory_path() / "sd-private-XXXXXX").string();
    path = ::mkdtemp(pattern.data());
  }
  ~TempFolder() {
    ::umask(umask_before);
    fs::remove_all(path);
  }
};

mode_t mode_of(const fs::path& file) {
  struct stat st {};
  EXPECT_EQ(::lstat(file.c_str(), &st), 0) << file;
  return st.st_mode & 07777;
}

TEST(PrivateFiles, EveryFolderMadeIsPrivateAndTheOnesThereKeepTheirMode) {
  TempFolder t;
  fs::create_directory(t.path / "shared");
  fs::permissions(t.path / "shared", fs::perms(0755), fs::perm_options::replace);
  create_private_folders(t.path / "shared" / "users" / "alice" / "projects");
  EXPECT_EQ(mode_of(t.path / "shared"), 0755u);
  EXPECT_EQ(mode_of(t.path / "shared" / "users"), 0700u);
  EXPECT_EQ(mode_of(t.path / "shared" / "users" / "alice"), 0700u);
  EXPECT_EQ(mode_of(t.path / "shared" / "users" / "alice" / "projects"), 0700u);
  create_private_folders(t.path / "shared" / "users");  // there already: no error
}

TEST(PrivateFiles, AFolderThatCannotBeMadeIsNamed) {
  TempFolder t;
  std::ofstream(t.path / "file") << "x";
  try {
    create_private_folders(t.path / "file" / "below");
    FAIL() << "no error";
  } catch (const std::system_error& e) {
    EXPECT_NE(std::string(e.what()).find("file/below"), std::string::npos) << e.what();
  }
}

TEST(PrivateFiles, AFileIsMadePrivateOnceAndALinkPlantedAtItsNameIsNotFollowed) {
  TempFolder t;
  create_private_file(t.path / "a.db");
  EXPECT_EQ(mode_of(t.path / "a.db"), 0600u);
  std::ofstream(t.path / "a.db") << "kept";
  create_private_file(t.path / "a.db");  // there already: left as it is
  EXPECT_EQ(fs::file_size(t.path / "a.db"), 4u);

  fs::create_symlink(t.path / "elsewhere.db", t.path / "link.db");
  create_private_file(t.path / "link.db");
  EXPECT_FALSE(fs::exists(t.path / "elsewhere.db")) << "followed the link";
}

TEST(PrivateFiles, ASaveNeverWritesThroughALinkPlantedAtItsTemporaryName) {
  TempFolder t;
  const fs::path victim = t.path / "victim.txt";
  std::ofstream(victim) << "precious";
  const fs::path target = t.path / "state.json";
  fs::create_symlink(victim, target.string() + ".tmp-" + std::to_string(::getpid()));
  replace_file_durably(target, "new state", 0600);
  std::ifstream in(victim);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "precious");
  std::ifstream saved(target);
  std::getline(saved, text);
  EXPECT_EQ(text, "new state");
}

}  // namespace
}  // namespace sd
