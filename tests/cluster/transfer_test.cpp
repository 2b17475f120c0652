// Files through a Shell, on both roads: std::filesystem here, and the sh/tar commands of the
// ssh road (run here by the stand-in ssh). Binary content must arrive byte for byte.
#include "cluster/transfer.hpp"

#include <gtest/gtest.h>

#include "cluster/support.hpp"

namespace sd::cluster {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::TempFolder;
using test_support::write_text;

constexpr std::size_t kWhole = std::size_t{1} << 20;

std::string every_byte() {
  std::string bytes;
  for (int repeat = 0; repeat < 300; ++repeat)
    for (int c = 0; c < 256; ++c) bytes.push_back(static_cast<char>(c));
  return bytes;
}

// The same tests run on both roads.
class Transfer : public ::testing::TestWithParam<bool> {
 protected:
  TempFolder folder;
  Shell shell = GetParam() ? test_support::fake_ssh_shell(folder.path) : Shell::here();
  std::string at(const std::string& relative) const { return (folder.path / relative).string(); }
};

TEST_P(Transfer, WritesCreatingFoldersAndReadsBackBinaryContent) {
  const std::string content = every_byte();
  write_file(shell, at("a/b c/data.bin"), content);
  EXPECT_EQ(read_text(folder.path / "a/b c/data.bin"), content);
  EXPECT_EQ(read_file(shell, at("a/b c/data.bin"), kWhole), content);
  write_file(shell, at("a/b c/data.bin"), "shorter");
  EXPECT_EQ(read_file(shell, at("a/b c/data.bin"), kWhole), "shorter");
  write_file(shell, at("empty"), "");
  EXPECT_EQ(read_file(shell, at("empty"), kWhole), "");
  EXPECT_FALSE(fs::exists(folder.path / "a/b c/data.bin.swarmdesign-part"));
}

TEST_P(Transfer, AReadIsBoundedToTheFilesEnd) {
  const std::string content = every_byte();  // 76 800 bytes
  write_file(shell, at("log"), content);
  EXPECT_EQ(read_file(shell, at("log"), 1000), content.substr(content.size() - 1000));
  EXPECT_EQ(read_file(shell, at("log"), content.size()), content);
  EXPECT_EQ(read_file(shell, at("log"), 0), "");
}

TEST_P(Transfer, MakesFilesExecutableWhenAsked) {
  write_file(shell, at("job.sh"), "#!/bin/sh\necho ran\n", true);
  EXPECT_EQ(run_command({at("job.sh")}).out, "ran\n");
  write_file(shell, at("plain.txt"), "x");
  EXPECT_EQ(fs::status(folder.path / "plain.txt").permissions() & fs::perms::owner_exec, fs::perms::none);
}

TEST_P(Transfer, TellsWhatExists) {
  write_file(shell, at("here.txt"), "x");
  EXPECT_TRUE(exists(shell, at("here.txt")));
  EXPECT_TRUE(exists(shell, folder.path.string()));
  EXPECT_FALSE(exists(shell, at("absent.txt")));
  EXPECT_EQ(read_file(shell, at("absent.txt"), kWhole), std::nullopt);
}

TEST_P(Transfer, ReportsWhatCannotBeWrittenOrRead) {
  write_file(shell, at("file"), "x");
  try {
    write_file(shell, at("file/inside"), "y");  // a file stands where the folder should be
    FAIL() << "no exception";
  } catch (const ClusterError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("cannot write " + at("file/inside") + " on " + shell.describe() + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_THROW(read_file(shell, folder.path.string(), kWhole), ClusterError);  // a folder
}

TEST_P(Transfer, FetchesAFolderReplacingFilesOfTheSameName) {
  const std::string content = every_byte();
  write_file(shell, at("remote/results.bin"), content);
  write_file(shell, at("remote/runs/0/trace.json"), "{\"x\": 1}");
  write_file(shell, at("remote/runs/1/trace.json"), "{\"x\": 2}");
  write_text(folder.path / "local-placeholder", "");
  fs::create_directories(folder.path / "local/runs/0");
  write_text(folder.path / "local/runs/0/trace.json", "old");
  write_text(folder.path / "local/kept.txt", "mine");

  fetch_folder(shell, at("remote"), folder.path / "local");
  EXPECT_EQ(read_text(folder.path / "local/results.bin"), content);
  EXPECT_EQ(read_text(folder.path / "local/runs/0/trace.json"), "{\"x\": 1}");
  EXPECT_EQ(read_text(folder.path / "local/runs/1/trace.json"), "{\"x\": 2}");
  EXPECT_EQ(read_text(folder.path / "local/kept.txt"), "mine");

  fetch_folder(shell, at("remote"), folder.path / "new/deeper");  // created
  EXPECT_EQ(read_text(folder.path / "new/deeper/results.bin"), content);
  EXPECT_THROW(fetch_folder(shell, at("no-such-folder"), folder.path / "x"), ClusterError);
}

TEST_P(Transfer, ExpandsALeadingTildeOnTheSideWhereTheFileIs) {
  const test_support::ScopedEnv home("HOME", folder.path.string());
  const Shell tilde_shell = GetParam() ? test_support::fake_ssh_shell(folder.path) : Shell::here();
  write_file(tilde_shell, "~/from tilde/x.txt", "tilde");
  EXPECT_EQ(read_text(folder.path / "from tilde/x.txt"), "tilde");
  EXPECT_TRUE(exists(tilde_shell, "~/from tilde"));
  EXPECT_EQ(read_file(tilde_shell, "~/from tilde/x.txt", kWhole), "tilde");
  fetch_folder(tilde_shell, "~/from tilde", folder.path / "copy");
  EXPECT_EQ(read_text(folder.path / "copy/x.txt"), "tilde");
}

INSTANTIATE_TEST_SUITE_P(BothRoads, Transfer, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& road) { return road.param ? "Ssh" : "Here"; });

TEST(LocalPath, ExpandsTheHomeFolder) {
  const test_support::ScopedEnv home("HOME", "/home/someone");
  EXPECT_EQ(local_path("~/a/b"), fs::path("/home/someone/a/b"));
  EXPECT_EQ(local_path("~"), fs::path("/home/someone"));
  EXPECT_EQ(local_path("/abs/~/x"), fs::path("/abs/~/x"));
}

}  // namespace
}  // namespace sd::cluster
