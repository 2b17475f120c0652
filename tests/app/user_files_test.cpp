// A mission a user keeps on a shared server may name an Arlequin module-set folder: as an
// attacker would, it names another account's folder (absolute and by ".."), a folder of
// devices, and a folder of its own with a weight document linked to another account's. Each is
// refused with the words a missing folder gets; the user's own folder is read. A link planted
// as a user's projects folder does not move their scope to its target.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/errors.hpp"
#include "app/home.hpp"
#include "app/user_files.hpp"
#include "modules/arlequin_module_set.hpp"
#include "storage/workspace.hpp"
#include "test_paths.hpp"

namespace sd::app {
namespace {

namespace fs = std::filesystem;

class ModuleSetScope : public ::testing::Test {
 protected:
  void SetUp() override {
    home_ = fs::temp_directory_path() / ("sd-user-files-" + std::to_string(::getpid()));
    fs::remove_all(home_);
    alice_projects_ = home_ / storage::Workspace::projects_folder(alice_);
    bob_projects_ = home_ / storage::Workspace::projects_folder(bob_);
    copy_set(alice_projects_ / "p" / "set");
    copy_set(bob_projects_ / "q" / "set");
  }
  void TearDown() override { fs::remove_all(home_); }

  static void copy_set(const fs::path& to) {
    fs::create_directories(to);
    for (const char* name : {"exploration", "stop", "phototaxis", "antiphototaxis", "attraction", "repulsion"})
      fs::copy_file(fs::path(::sd::test::source_dir()) / "data/arlequin-demiurge" / (std::string(name) + ".json"),
                    to / (std::string(name) + ".json"));
  }
  // A mission file in Alice's project that names `set` as its module set.
  fs::path mission_naming(const std::string& set) const {
    const fs::path file = alice_projects_ / "p" / "mission.json";
    nlohmann::json document = nlohmann::json::parse(
        std::ifstream(fs::path(::sd::test::source_dir()) / "missions" / "aac.json"), nullptr, true, /*ignore_comments=*/true);
    document["arlequin_modules"] = set;
    std::ofstream(file) << document.dump(1);
    return file;
  }
  std::string refusal(const std::string& set) const {
    try {
      load_requested_mission(mission_naming(set).string(), scope());
    } catch (const std::exception& e) {
      return e.what();
    }
    return "accepted";
  }
  FileScope scope() const { return FileScope::own_projects(Home(home_), alice_); }

  storage::User alice_{1, "alice", 0}, bob_{2, "bob", 0};
  fs::path home_, alice_projects_, bob_projects_;
};

TEST_F(ModuleSetScope, AUsersOwnFolderIsRead) {
  const Mission mission = load_requested_mission(mission_naming("set").string(), scope());
  ASSERT_NE(mission.arlequin_modules, nullptr);
  EXPECT_EQ(mission.arlequin_modules->weights, arlequin::load_module_set("demiurge")->weights);
}

TEST_F(ModuleSetScope, AnotherAccountsFolderIsAnsweredAsAMissingOne) {
  const std::string missing = refusal((alice_projects_ / "p" / "nothing").string());
  EXPECT_NE(missing.find("neither swarmdesign, demiurge nor a folder"), std::string::npos) << missing;
  for (const std::string& set : {(bob_projects_ / "q" / "set").string(), std::string("../../../bob/projects/q/set"),
                                std::string("/dev"), std::string("/etc")}) {
    std::string said = refusal(set);
    EXPECT_NE(said.find("neither swarmdesign, demiurge nor a folder"), std::string::npos) << set << ": " << said;
  }
  EXPECT_THROW(with_requested_arlequin_modules(load_requested_mission("aac", scope()), (bob_projects_ / "q" / "set").string(),
                                               scope()),
               InvalidRequest);
}

TEST_F(ModuleSetScope, AWeightDocumentLinkedOutIsNotRead) {
  const fs::path own = alice_projects_ / "p" / "set" / "stop.json";
  fs::remove(own);
  fs::create_symlink(bob_projects_ / "q" / "set" / "stop.json", own);
  const std::string said = refusal("set");
  EXPECT_NE(said.find("is not a file of your projects"), std::string::npos) << said;
  fs::remove(own);  // a missing document gets the same words
  EXPECT_EQ(refusal("set"), said);
  // The CLI on one's own machine follows the link, as it follows any path the user types.
  fs::create_symlink(bob_projects_ / "q" / "set" / "stop.json", own);
  EXPECT_NE(load_requested_mission(mission_naming("set").string(), FileScope::local()).arlequin_modules, nullptr);
}

TEST_F(ModuleSetScope, ALinkPlantedAsAUsersProjectsFolderDoesNotMoveTheirScope) {
  // Someone with write access to the home replaces Carol's projects folder by a link to Bob's:
  // Carol's scope stays where her folder should be, so Bob's files are not hers through it.
  const storage::User carol{3, "carol", 0};
  const fs::path carols = home_ / storage::Workspace::projects_folder(carol);
  fs::create_directories(carols.parent_path());
  fs::create_symlink(bob_projects_, carols);
  const FileScope scope = FileScope::own_projects(Home(home_), carol);
  EXPECT_FALSE(scope.allows(carols / "q" / "set" / "stop.json"));
  EXPECT_FALSE(scope.allows(bob_projects_ / "q" / "set" / "stop.json"));
  EXPECT_THROW(scope.read((carols / "q" / "set" / "stop.json").string(), "weight document"), NotFound);
  // Without the link, her own folder is hers.
  fs::remove(carols);
  fs::create_directories(carols / "r");
  std::ofstream(carols / "r" / "notes.txt") << "mine";
  EXPECT_EQ(scope.read((carols / "r" / "notes.txt").string(), "notes"), "mine");
}

}  // namespace
}  // namespace sd::app
