// Files a server reads on its own, not because a user named them: a design's assessment.json,
// design.db, pseudo-reality.json, and an EvoStick design's document and state file. Someone
// who can write into a design folder (the server's own Unix user, as the server makes its
// folders 0700) plants a symbolic or a hard link at their names, leading to another account's
// file: the server must not serve or open what the link leads to.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/design_assessment.hpp"
#include "app/design_method.hpp"
#include "core/bounded_file.hpp"
#include "storage/sqlite.hpp"

namespace sd::test {
namespace {

namespace fs = std::filesystem;

const std::string kSecret = "SECRET-5e0a77";  // in another account's files

class ServerReadFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("sd-server-reads-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    mine_ = root_ / "alice" / "design-1";
    theirs_ = root_ / "bob" / "design-1";
    fs::create_directories(mine_);
    fs::create_directories(theirs_);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string assessment_refusal() const {
    try {
      const auto document = app::read_design_assessment(mine_);
      return document ? "served: " + document->dump() : "absent";
    } catch (const std::exception& e) {
      return e.what();
    }
  }

  fs::path root_, mine_, theirs_;
};

TEST_F(ServerReadFiles, AnAssessmentLinkedToAnotherFileIsNotServed) {
  std::ofstream(theirs_ / "assessment.json") << R"({"secret": ")" << kSecret << R"("})";
  EXPECT_EQ(assessment_refusal(), "absent");

  fs::create_symlink(theirs_ / "assessment.json", app::design_assessment_file(mine_));
  std::string said = assessment_refusal();
  EXPECT_NE(said.find("is a link; it is not read"), std::string::npos) << said;
  EXPECT_EQ(said.find(kSecret), std::string::npos) << said;
  EXPECT_EQ(said.find(root_.string()), std::string::npos) << "the server's folders in: " << said;

  fs::remove(app::design_assessment_file(mine_));
  fs::create_hard_link(theirs_ / "assessment.json", app::design_assessment_file(mine_));
  said = assessment_refusal();
  EXPECT_NE(said.find("is a link; it is not read"), std::string::npos) << said;
  EXPECT_EQ(said.find(kSecret), std::string::npos) << said;

  // A dangling link is not "no assessment yet" either: something is at that name.
  fs::remove(app::design_assessment_file(mine_));
  fs::create_symlink(root_ / "nowhere.json", app::design_assessment_file(mine_));
  EXPECT_EQ(assessment_refusal().rfind("served", 0), std::string::npos);
  EXPECT_NE(assessment_refusal(), "absent");

  // The design's own file is read.
  fs::remove(app::design_assessment_file(mine_));
  std::ofstream(app::design_assessment_file(mine_)) << R"({"mine": 1})";
  EXPECT_EQ(assessment_refusal(), R"(served: {"mine":1})");
}

TEST_F(ServerReadFiles, ADesignDatabaseLinkedToAnotherIsNotOpened) {
  {
    storage::Database theirs(theirs_ / "design.db");
    theirs.execute("CREATE TABLE race(secret TEXT)");
    theirs.execute("INSERT INTO race VALUES ('" + kSecret + "')");
  }
  fs::create_symlink(theirs_ / "design.db", mine_ / "design.db");
  try {
    storage::Database opened(mine_ / "design.db", /*create=*/false);
    ADD_FAILURE() << "a design.db linked to another account's was opened";
  } catch (const storage::DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
  }
  EXPECT_THROW(storage::Database(mine_ / "design.db", /*create=*/true), storage::DatabaseError);

  fs::remove(mine_ / "design.db");
  fs::create_hard_link(theirs_ / "design.db", mine_ / "design.db");
  try {
    storage::Database opened(mine_ / "design.db", /*create=*/false);
    ADD_FAILURE() << "a design.db hard-linked to another account's was opened";
  } catch (const storage::DatabaseError& e) {
    EXPECT_NE(std::string(e.what()).find("hard link"), std::string::npos) << e.what();
  }

  // A database whose folder's path goes through a link (where an administrator put a home) opens.
  fs::remove(mine_ / "design.db");
  fs::create_symlink(theirs_, root_ / "bob-home-link");
  storage::Database through_a_folder_link(root_ / "bob-home-link" / "design.db", /*create=*/false);
  through_a_folder_link.execute("SELECT count(*) FROM race");
}

TEST_F(ServerReadFiles, EveryOtherFileOfADesignFolderIsReadOnlyAsTheFolderOwnEntry) {
  // The names a server reads by itself in a design folder besides the two above.
  for (const std::string name : {"pseudo-reality.json", "evostick.json", "assessment.json"}) {
    SCOPED_TRACE(name);
    std::ofstream(theirs_ / name) << R"({"secret": ")" << kSecret << R"("})";
    const auto read = [&]() -> std::string {
      try {
        return read_folder_file(mine_, name, "file").text;
      } catch (const FileReadError& e) {
        return e.problem == FileProblem::Outside ? "outside" : e.problem == FileProblem::Missing ? "missing" : "other";
      }
    };
    EXPECT_EQ(read(), "missing");
    fs::create_symlink(theirs_ / name, mine_ / name);
    EXPECT_EQ(read(), "outside");
    fs::remove(mine_ / name);
    fs::create_hard_link(theirs_ / name, mine_ / name);
    EXPECT_EQ(read(), "outside");
    fs::remove(mine_ / name);
    // A link to a file of the same folder, under the same name from elsewhere, is not it either.
    fs::create_symlink(mine_ / "other.json", mine_ / name);
    std::ofstream(mine_ / "other.json") << "{}";
    EXPECT_EQ(read(), "outside");
    fs::remove(mine_ / name);
    std::ofstream(mine_ / name) << R"({"mine": 1})";
    EXPECT_EQ(read(), R"({"mine": 1})");
    // The folder's own path may go through a link (where an administrator put a home).
    fs::create_directory_symlink(mine_, root_ / "alice-link");
    EXPECT_EQ(read_folder_file(root_ / "alice-link", name, "file").text, R"({"mine": 1})");
    fs::remove(root_ / "alice-link");
    fs::remove(mine_ / name);
    fs::remove(mine_ / "other.json");
  }
  // An EvoStick design resumed by a server reads its state file only as its folder's own.
  std::ofstream(theirs_ / "evolution.json") << R"({"secret": ")" << kSecret << R"("})";
  fs::create_symlink(theirs_ / "evolution.json", mine_ / "evolution.json");
  storage::PlannedDesign planned;
  planned.mission = "aac";
  planned.method = "evostick";
  planned.budget = 1000;
  try {
    app::design_method("evostick").run(planned, mine_, {.threads = 1});
    ADD_FAILURE() << "resumed from a state file linked to another account's";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()), "the EvoStick design's state file is a link or not a file; it is not read");
  }
  fs::remove(mine_ / "evolution.json");
  fs::create_hard_link(theirs_ / "evolution.json", mine_ / "evolution.json");
  EXPECT_THROW(app::design_method("evostick").run(planned, mine_, {.threads = 1}), std::runtime_error);
  fs::remove(mine_ / "evolution.json");

  // What the page's monitor shows of an EvoStick design goes through it: a planted link is refused.
  fs::create_symlink(theirs_ / "evostick.json", mine_ / "evostick.json");
  try {
    const nlohmann::json served = app::design_method("evostick").document(mine_);
    ADD_FAILURE() << "served " << served.dump();
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()).find(kSecret), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sd::test
