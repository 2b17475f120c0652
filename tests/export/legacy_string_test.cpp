// export --argos: control software as the ARGoS3-AutoMoDe code base of its flavour reads it.
// The contract is the legacy reader's inverse: export, then parse with that flavour, gives the
// same control software, for hand-written FSMs and trees, random ones of every flavour's
// design space, and every one-digit string the calibration runs gave ARGoS.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "control/config_string.hpp"
#include "core/rng.hpp"
#include "design/design_space.hpp"
#include "design/sampling.hpp"
#include "export/legacy_string.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

using argos::ExportOptions;
using argos::ExportRefused;
using argos::to_legacy_string;
using argos::TreeForm;

ControlSoftware read_back(const argos::LegacyString& exported) {
  ParseOptions options;
  options.legacy_flavour = exported.flavour;
  return parse_control_software(exported.text, options);
}

/// The message of the ExportRefused that exporting `software` must throw (empty, and the test
/// fails, if it exports).
std::string refusal(const ControlSoftware& software, const ExportOptions& options = {}) {
  try {
    to_legacy_string(software, options);
  } catch (const ExportRefused& e) {
    return e.what();
  }
  ADD_FAILURE() << "exported, but should have been refused";
  return {};
}

/// Token name -> value of a configuration string (order-free comparison).
std::map<std::string, double> token_values(const std::string& text) {
  const auto tokens = split_tokens(text);
  std::map<std::string, double> values;
  for (std::size_t i = 1; i + 1 < tokens.size(); i += 2) values[tokens[i]] = std::stod(tokens[i + 1]);
  return values;
}

/// Every module id in an exported string (--s, --c, --a tokens).
std::vector<int> module_ids(const std::string& text) {
  const auto tokens = split_tokens(text);
  std::vector<int> ids;
  for (std::size_t i = 1; i + 1 < tokens.size(); i += 2) {
    const char c = tokens[i].size() > 2 ? tokens[i][2] : ' ';
    const bool digit_follows = tokens[i].size() > 3 && std::isdigit(static_cast<unsigned char>(tokens[i][3]));
    if ((c == 's' || c == 'c' || c == 'a') && digit_follows) ids.push_back(std::stoi(tokens[i + 1]));
  }
  return ids;
}

TEST(export_LegacyString, ChocolateFsmLosesTheFlavourDigit) {
  const ControlSoftware software = parse_control_software(
      "--fsm-config --nstates 2 --s0 14 --att0 3.25 --n0 1 --n0x0 0 --c0x0 13 --p0x0 5 --w0x0 10.2 "
      "--s1 10 --rwm1 50 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.5");
  const auto exported = to_legacy_string(software);
  EXPECT_EQ(exported.flavour, Flavour::Chocolate);
  EXPECT_EQ(exported.text,
            "--fsm-config --nstates 2 --s0 4 --att0 3.25 --n0 1 --n0x0 0 --c0x0 3 --p0x0 5 --w0x0 10.2 "
            "--s1 0 --rwm1 50 --n1 1 --n1x0 0 --c1x0 5 --p1x0 0.5");
  EXPECT_NE(exported.reader.find("master"), std::string::npos);
  EXPECT_EQ(read_back(exported), software);
}

TEST(export_LegacyString, MapleTreesUseTheRootnodeFormWhenTheyHaveMaplesShape) {
  const ControlSoftware software = parse_control_software(
      "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 0.27 --n01 5 --a01 44 "
      "--att01 4.93 --p01 0 --n1 0 --nchild1 2 --n10 6 --c10 43 --p10 2 --w10 5 --n11 5 --a11 42 --p11 0");
  const auto exported = to_legacy_string(software);
  EXPECT_EQ(exported.flavour, Flavour::Maple);
  EXPECT_EQ(exported.text,
            "--bt-config --rootnode 0 --nchildsroot 2 --n0 0 --nc0 1 --c0x0 0 --p0x0 0.27 --a0 4 --att0 4.93 "
            "--n1 0 --nc1 1 --c1x0 3 --p1x0 2 --w1x0 5 --a1 2");
  EXPECT_EQ(read_back(exported), software);

  ExportOptions nroot;
  nroot.tree_form = TreeForm::NRoot;
  const auto generic = to_legacy_string(software, nroot);
  EXPECT_EQ(generic.text.rfind("--bt-config --nroot 3", 0), 0u) << generic.text;
  EXPECT_NE(generic.reader.find("BehaviorTree"), std::string::npos);
  EXPECT_EQ(read_back(generic), software);
}

TEST(export_LegacyString, ATreeMapleCannotSayIsRefusedInTheRootnodeForm) {
  // An action that may succeed: Maple's --rootnode form has no success probability.
  const ControlSoftware software = parse_control_software(
      "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 45 --p00 0.5 --n01 5 --a01 41 --p01 0.3");
  const auto exported = to_legacy_string(software);
  EXPECT_NE(exported.text.find("--nroot"), std::string::npos);
  EXPECT_EQ(read_back(exported), software);
  ExportOptions rootnode;
  rootnode.tree_form = TreeForm::RootNode;
  EXPECT_THROW(to_legacy_string(software, rootnode), ExportRefused);
}

/// Random control software of one flavour's design space, `architectures` as run-design names them.
std::vector<ControlSoftware> sampled(Flavour flavour, bool fsm, bool bt, int count, std::uint64_t seed) {
  design::DesignSpaceRequest request;
  request.fsm = fsm;
  request.bt = bt;
  request.flavours = {flavour};
  const auto space = design::build_design_space(design::resolve_design_space(request));
  Rng rng(seed);
  std::vector<ControlSoftware> out;
  for (int k = 0; k < count; ++k) out.push_back(parse_control_software(space.render(design::sample_uniform(space, rng))));
  return out;
}

struct FlavourCase {
  Flavour flavour;
  bool trees;         // the flavour's code base reads behaviour trees
  bool one_digit;     // it reads one-digit ids (Coconut and Arlequin: Demiurge's two digits)
};

class export_EveryFlavour : public ::testing::TestWithParam<FlavourCase> {};

TEST_P(export_EveryFlavour, RandomDesignsReadBackAsTheSameControlSoftware) {
  const FlavourCase c = GetParam();
  int exported_count = 0, refused_count = 0;
  for (const ControlSoftware& software : sampled(c.flavour, true, c.trees, 400, 2026 + static_cast<int>(c.flavour))) {
    ExportOptions options;
    options.flavour = c.flavour;
    argos::LegacyString exported;
    try {
      exported = to_legacy_string(software, options);
    } catch (const ExportRefused& e) {
      // Only Demiurge refuses anything of its own flavour: a neighbour count whose xi it cannot read.
      ASSERT_FALSE(c.one_digit) << e.what() << "\n" << to_config_string(software);
      EXPECT_NE(std::string(e.what()).find("xi"), std::string::npos) << e.what();
      ++refused_count;
      continue;
    }
    ++exported_count;
    EXPECT_EQ(exported.flavour, c.flavour);
    EXPECT_EQ(read_back(exported), software) << exported.text;
    // Inferred without --flavour too.
    EXPECT_EQ(to_legacy_string(software).text, exported.text);
    for (const int id : module_ids(exported.text)) {
      if (c.one_digit) EXPECT_LT(id, 10) << exported.text;
      else EXPECT_EQ(id / 10, static_cast<int>(c.flavour)) << exported.text;
    }
  }
  if (c.one_digit) {
    EXPECT_EQ(exported_count, 400);
  } else {
    // Demiurge cannot be told most neighbour counts' xi: over half the random designs have one.
    EXPECT_GT(exported_count, 100) << refused_count << " refused";
    EXPECT_GT(refused_count, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Flavours, export_EveryFlavour,
                         ::testing::Values(FlavourCase{Flavour::Chocolate, true, true},
                                           FlavourCase{Flavour::TuttiFrutti, false, true},
                                           FlavourCase{Flavour::Maple, true, true},
                                           FlavourCase{Flavour::Coconut, true, false},
                                           FlavourCase{Flavour::Arlequin, true, false}),
                         [](const ::testing::TestParamInfo<FlavourCase>& test) {
                           return std::string(flavour_name(test.param.flavour));
                         });

TEST(export_LegacyString, TuttiFruttiTreesAreRefusedForItsCodeBaseHasNone) {
  const auto trees = sampled(Flavour::TuttiFrutti, false, true, 1, 7);
  const std::string message = refusal(trees.front());
  EXPECT_NE(message.find("finite-state machines only"), std::string::npos) << message;
}

TEST(export_LegacyString, MixedDesignsAreRefusedNamingEveryModule) {
  const ControlSoftware mixed = parse_control_software(
      "--fsm-config --nstates 2 --s0 10 --rwm0 5 --n0 1 --n0x0 0 --c0x0 27 --p0x0 0.5 --l0x0 2 --s1 24 --att1 2 --cle1 4");
  const std::string message = refusal(mixed);
  EXPECT_NE(message.find("mixes flavours"), std::string::npos) << message;
  EXPECT_NE(message.find("state 0: 10 Exploration (chocolate)"), std::string::npos) << message;
  EXPECT_NE(message.find("transition 0 of state 0: 27 ColorDetection (tuttifrutti)"), std::string::npos) << message;
  EXPECT_NE(message.find("state 1: 24 Attraction (tuttifrutti)"), std::string::npos) << message;
  ExportOptions chocolate;
  chocolate.flavour = Flavour::Chocolate;
  const std::string as_chocolate = refusal(mixed, chocolate);
  EXPECT_EQ(as_chocolate.find("10 Exploration"), std::string::npos) << as_chocolate;  // Chocolate's own module is fine
  EXPECT_NE(as_chocolate.find("27 ColorDetection (tuttifrutti)"), std::string::npos) << as_chocolate;
  EXPECT_NE(as_chocolate.find("24 Attraction (tuttifrutti)"), std::string::npos) << as_chocolate;
  // A tree names its nodes.
  const ControlSoftware tree = parse_control_software(
      "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 15 --p00 0.5 --n01 5 --a01 42 --p01 0");
  const std::string of_tree = refusal(tree);
  EXPECT_NE(of_tree.find("condition node 00: 15 FixedProbability (chocolate)"), std::string::npos) << of_tree;
  EXPECT_NE(of_tree.find("action node 01: 42 Phototaxis (maple)"), std::string::npos) << of_tree;
}

TEST(export_LegacyString, DemiurgeNeighbourCountsExportOnlyWhenItReadsTheirXi) {
  // Demiurge reads xi from --n0x0, the destination token: 0 here, so xi 5 cannot be said.
  const ControlSoftware refused = parse_control_software(
      "--fsm-config --nstates 2 --s0 31 --n0 1 --n0x0 0 --c0x0 33 --p0x0 5 --w0x0 2 --s1 31");
  const std::string of_fsm = refusal(refused);
  EXPECT_NE(of_fsm.find("transition 0 of state 0: 33 NeighborsCount (coconut) has xi = 5"), std::string::npos)
      << of_fsm;
  // From state 0 of three, destination 2 is written --n0x1 1: xi 1 is what Demiurge reads.
  const ControlSoftware exported = parse_control_software(
      "--fsm-config --nstates 3 --s0 31 --n0 2 --n0x0 0 --c0x0 35 --p0x0 0.5 --n0x1 1 --c0x1 34 --p0x1 1 --w0x1 3 "
      "--s1 31 --s2 31");
  const auto result = to_legacy_string(exported);
  EXPECT_EQ(result.text, to_config_string(exported));
  EXPECT_NE(result.reader.find("Demiurge"), std::string::npos);
  // Demiurge's tree builder hands a condition only the tokens from --c<id> on: no xi at all.
  const ControlSoftware tree = parse_control_software(
      "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 53 --p00 6 --w00 1 --n01 5 --a01 51 --p01 0");
  const std::string of_tree = refusal(tree);
  EXPECT_NE(of_tree.find("condition node 00: 53 NeighborsCount (arlequin): Demiurge's tree builder"),
            std::string::npos)
      << of_tree;
}

TEST(export_LegacyString, EvoStickNetworksAreNotModularControlSoftware) {
  std::string text = "--nn-config";
  for (int o = 0; o < 2; ++o)
    for (int i = 0; i < 25; ++i) text += " --w" + std::to_string(o) + "x" + std::to_string(i) + " 0.5";
  EXPECT_THROW(to_legacy_string(parse_control_software(text)), ExportRefused);
}

/// The strings ARGoS ran in the calibration (tests/data): export gives them back.
TEST(export_LegacyString, CalibrationControllersExportAsTheStringsArgosRan) {
  int checked = 0;
  for (const char* file : {"argos-reference-2.csv", "argos-reference-3.csv"}) {
    std::ifstream in(std::string(::sd::test::source_dir()) + "/tests/data/" + file);
    ASSERT_TRUE(in) << file;
    std::string line;
    std::getline(in, line);
    std::map<std::string, std::pair<std::string, std::string>> controllers;  // config -> flavour
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::stringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
      ASSERT_GE(cells.size(), 5u) << line;
      controllers[cells[4]] = {cells[3], cells[2]};
    }
    for (const auto& [config, what] : controllers) {
      const auto& [legacy_flavour, architecture] = what;
      ParseOptions parse;
      parse.legacy_flavour = legacy_flavour.empty() ? Flavour::Chocolate : *flavour_from_name(legacy_flavour);
      const ControlSoftware software = parse_control_software(config, parse);
      ExportOptions options;
      if (architecture == "bt") options.tree_form = TreeForm::NRoot;  // the BehaviorTree branch ran the trees
      const auto exported = to_legacy_string(software, options);
      // Chocolate rows hold two-digit ids; ARGoS ran them with 10 subtracted.
      std::map<std::string, double> ran = token_values(config);
      if (legacy_flavour.empty())
        for (auto& [token, value] : ran)
          if (token.rfind("--s", 0) == 0 || token.rfind("--c", 0) == 0) value -= 10;
      EXPECT_EQ(token_values(exported.text), ran) << config << "\n" << exported.text;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 40);  // 15 Chocolate FSMs and 10 Maple trees, 15 TuttiFrutti FSMs
}

}  // namespace
}  // namespace sd
