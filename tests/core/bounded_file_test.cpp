// Reading a file a user named: regular files only, bounded, checked on what was opened, and
// refusals that never quote the file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/bounded_file.hpp"
#include "core/json_syntax.hpp"

namespace sd {
namespace {

class BoundedFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() / ("sd-bounded-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_ / "inside");
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  FileProblem problem_of(const std::filesystem::path& path, std::size_t bound = kMaxInputFileBytes,
                         const PathRule& rule = {}) {
    try {
      read_bounded_file(path, "test file", bound, rule);
    } catch (const FileReadError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
      return e.problem;
    }
    ADD_FAILURE() << path << " was read";
    return FileProblem::Unreadable;
  }

  std::filesystem::path folder_;
};

TEST_F(BoundedFile, ReadsARegularFileWholeAndSaysWhereItReallyIs) {
  std::ofstream(folder_ / "inside" / "a.json") << "{\"a\": 1}";
  std::filesystem::create_symlink(folder_ / "inside" / "a.json", folder_ / "link.json");
  const FileText read = read_bounded_file(folder_ / "link.json", "test file");
  EXPECT_EQ(read.text, "{\"a\": 1}");
  EXPECT_EQ(read.real_path, std::filesystem::canonical(folder_ / "inside" / "a.json"));
}

TEST_F(BoundedFile, RefusesDevicesFoldersFifosAndFilesOverTheBound) {
  EXPECT_EQ(problem_of("/dev/zero"), FileProblem::NotRegular);
  EXPECT_EQ(problem_of("/dev/urandom"), FileProblem::NotRegular);
  EXPECT_EQ(problem_of(folder_), FileProblem::NotRegular);
  ASSERT_EQ(::mkfifo((folder_ / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(problem_of(folder_ / "fifo"), FileProblem::NotRegular) << "opening must not wait for a writer";
  std::ofstream(folder_ / "eleven") << "01234567890";
  EXPECT_EQ(problem_of(folder_ / "eleven", 10), FileProblem::TooLarge);
  EXPECT_EQ(read_bounded_file(folder_ / "eleven", "test file", 11).text, "01234567890");
  EXPECT_EQ(problem_of(folder_ / "missing"), FileProblem::Missing);
}

TEST_F(BoundedFile, TheRuleIsAskedAboutTheFileThatWasOpenedNotTheNameGiven) {
  const auto inside = std::filesystem::canonical(folder_ / "inside");
  const PathRule only_inside = [&](const std::filesystem::path& real) { return is_within(real, inside); };
  std::ofstream(folder_ / "secret") << "secret";
  std::filesystem::create_symlink(folder_ / "secret", folder_ / "inside" / "link");
  std::filesystem::create_symlink("/dev/zero", folder_ / "inside" / "zero");
  EXPECT_EQ(problem_of(folder_ / "inside" / "link", kMaxInputFileBytes, only_inside), FileProblem::Outside);
  EXPECT_EQ(problem_of(folder_ / "inside" / "zero", kMaxInputFileBytes, only_inside), FileProblem::Outside);
  EXPECT_EQ(problem_of(folder_ / "inside" / ".." / "secret", kMaxInputFileBytes, only_inside), FileProblem::Outside);
  try {
    read_bounded_file(folder_ / "inside" / "link", "test file", kMaxInputFileBytes, only_inside);
  } catch (const FileReadError& e) {
    EXPECT_EQ(std::string(e.what()).find("secret\""), std::string::npos);
  }
}

TEST(IsWithin, ComparesWholeComponents) {
  EXPECT_TRUE(is_within("/a/b/c", "/a/b"));
  EXPECT_TRUE(is_within("/a/b", "/a/b"));
  EXPECT_TRUE(is_within("/a/b/c", "/a/b/"));
  EXPECT_FALSE(is_within("/a/bc", "/a/b"));
  EXPECT_FALSE(is_within("/a", "/a/b"));
  EXPECT_FALSE(is_within("/a/b", ""));
}

TEST(JsonSyntaxError, SaysWhereAndWhatButNotTheText) {
  const std::string text = "{\n  \"name\": \"hunter2\",\n  oops\n}";
  try {
    const nlohmann::json parsed = nlohmann::json::parse(text);
    FAIL() << "parsed " << parsed.dump();
  } catch (const nlohmann::json::parse_error& e) {
    ASSERT_NE(std::string(e.what()).find("last read"), std::string::npos) << "the parser's own message quotes";
    const std::string said = json_syntax_error(e, text);
    EXPECT_NE(said.find("(line 3, column 3)"), std::string::npos) << said;
    EXPECT_NE(said.find("syntax error"), std::string::npos) << said;
    EXPECT_EQ(said.find("oops"), std::string::npos) << said;
    EXPECT_EQ(said.find("o'"), std::string::npos) << said;
  }
}

}  // namespace
}  // namespace sd
