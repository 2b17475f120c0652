// The export commands end to end, as a user runs them.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "run_cli.hpp"

namespace {

using Result = sd::test::CliResult;
Result run(const std::string& args) { return sd::test::run_cli(args); }

TEST(export_Cli, ExportArgosPrintsTheOneDigitString) {
  const Result r = run("export --argos --fsm-config --nstates 1 --s0 24 --att0 2 --cle0 4");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "--fsm-config --nstates 1 --s0 4 --att0 2 --cle0 4\n");
  EXPECT_NE(r.err.find("tuttifrutti"), std::string::npos) << r.err;
}

TEST(export_Cli, AMixedDesignIsRefusedNamingItsModules) {
  const Result r = run("export --argos --fsm-config --nstates 2 --s0 10 --rwm0 5 --n0 1 --n0x0 0 --c0x0 15 --p0x0 1 "
                       "--s1 42");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("swarmdesign: error: cannot export for ARGoS"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("state 1: 42 Phototaxis (maple)"), std::string::npos) << r.err;
  const Result flavour = run("export --argos --flavour coconut --fsm-config --nstates 1 --s0 10 --rwm0 5");
  EXPECT_EQ(flavour.status, 2);
  EXPECT_NE(flavour.err.find("state 0: 10 Exploration (chocolate)"), std::string::npos) << flavour.err;
}

TEST(export_Cli, MissionExportArgosWritesAFileArgosCanParse) {
  const auto file = std::filesystem::temp_directory_path() / ("sd_export_" + std::to_string(::getpid()) + ".argos");
  const Result r = run("mission export-argos aac --out " + file.string() + " --loop-functions-dir /x/build");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Wrote "), std::string::npos);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(file.c_str()));
  EXPECT_EQ(std::string(doc.child("argos-configuration").child("loop_functions").attribute("library").value()),
            "/x/build/loop-functions/chocolate/AAC/libchocolate_aac_loopfunc.so");
  const Result bt = run("mission export-argos foraging --controller automode_controller_bt --out " + file.string());
  EXPECT_EQ(bt.status, 0) << bt.err;
  ASSERT_TRUE(doc.load_file(file.c_str()));
  EXPECT_TRUE(doc.child("argos-configuration").child("controllers").child("automode_controller_bt"));
  EXPECT_EQ(run("mission export-argos foraging --controller epuck_nn --out " + file.string()).status, 2);
  std::filesystem::remove(file);
  const Result help = run("mission export-argos --help");
  EXPECT_NE(help.out.find("Example:"), std::string::npos);
}

TEST(export_Cli, EveryExportCommandHasHelpWithAnExample) {
  for (const char* command : {"export", "mission export-argos", "status", "test-design"}) {
    const Result r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_NE(r.out.find("Example:\n  swarmdesign "), std::string::npos) << command << ":\n" << r.out;
  }
  for (const char* command : {"status", "test-design"})
    EXPECT_NE(run(std::string(command) + " --help").out.find("--argos"), std::string::npos) << command;
}

TEST(export_Cli, TestDesignArgosIsTextOnly) {
  const Result r = run("test-design --argos --json --fsm-config --nstates 1 --s0 11");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--argos prints a text line"), std::string::npos) << r.err;
}

TEST(export_Cli, ExportNeedsItsTarget) {
  const Result r = run("export --fsm-config --nstates 1 --s0 11");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--argos"), std::string::npos) << r.err;
}

}  // namespace
