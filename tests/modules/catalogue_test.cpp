// The module table: Chocolate ids 10-15 with the parameter domains of the irace grammar
// (ARGoS3-AutoMoDe's optimization/example/new_grammar.txt).
#include <gtest/gtest.h>

#include <cmath>

#include "modules/catalogue.hpp"

namespace sd {
namespace {

TEST(ModulesCatalogue, ChocolateBehavioursAndTheirParameters) {
  const char* names[] = {"Exploration", "Stop", "Phototaxis", "Anti-phototaxis", "Attraction", "Repulsion"};
  for (int d = 0; d < 6; ++d) {
    const ModuleSpec* spec = find_module(ModuleKind::Behaviour, 10 + d);
    ASSERT_NE(spec, nullptr) << 10 + d;
    EXPECT_EQ(spec->name, names[d]);
    EXPECT_EQ(spec->flavour(), Flavour::Chocolate);
    EXPECT_EQ(spec->digit(), d);
  }
  const ModuleSpec& rwm = *find_module(ModuleKind::Behaviour, 10);
  ASSERT_EQ(rwm.parameters.size(), 1u);
  EXPECT_EQ(rwm.parameters[0].token, "rwm");
  EXPECT_TRUE(rwm.parameters[0].accepts(1));
  EXPECT_TRUE(rwm.parameters[0].accepts(100));
  EXPECT_FALSE(rwm.parameters[0].accepts(0));
  EXPECT_FALSE(rwm.parameters[0].accepts(101));
  EXPECT_FALSE(rwm.parameters[0].accepts(2.5));
  EXPECT_TRUE(find_module(ModuleKind::Behaviour, 11)->parameters.empty());
  for (const int id : {14, 15}) {
    const ParameterSpec& p = find_module(ModuleKind::Behaviour, id)->parameters.at(0);
    EXPECT_TRUE(p.accepts(1.0));
    EXPECT_TRUE(p.accepts(4.99));
    EXPECT_TRUE(p.accepts(5.0));
    EXPECT_FALSE(p.accepts(0.999));
    EXPECT_FALSE(p.accepts(5.001));
  }
  EXPECT_EQ(find_module(ModuleKind::Behaviour, 16), nullptr);
  EXPECT_EQ(find_module(ModuleKind::Behaviour, 0), nullptr);
}

TEST(ModulesCatalogue, ChocolateConditionsAndTheirParameters) {
  const char* names[] = {"BlackFloor", "GrayFloor", "WhiteFloor", "NeighborsCount", "InvertedNeighborsCount",
                         "FixedProbability"};
  for (int d = 0; d < 6; ++d) {
    const ModuleSpec* spec = find_module(ModuleKind::Condition, 10 + d);
    ASSERT_NE(spec, nullptr);
    EXPECT_EQ(spec->name, names[d]);
    const bool neighbours = d == 3 || d == 4;
    ASSERT_EQ(spec->parameters.size(), neighbours ? 2u : 1u);
    EXPECT_EQ(spec->parameters[0].token, "p");
    if (neighbours) {
      EXPECT_EQ(spec->parameters[1].token, "w");
      EXPECT_TRUE(spec->parameters[0].accepts(1) && spec->parameters[0].accepts(10));
      EXPECT_FALSE(spec->parameters[0].accepts(0) || spec->parameters[0].accepts(11) || spec->parameters[0].accepts(2.5));
      EXPECT_TRUE(spec->parameters[1].accepts(0) && spec->parameters[1].accepts(20));
      EXPECT_FALSE(spec->parameters[1].accepts(-0.01) || spec->parameters[1].accepts(20.01));
    } else {
      EXPECT_TRUE(spec->parameters[0].accepts(0) && spec->parameters[0].accepts(1) && spec->parameters[0].accepts(0.5));
      EXPECT_FALSE(spec->parameters[0].accepts(-0.01) || spec->parameters[0].accepts(1.01));
    }
    EXPECT_EQ(spec->parameter_index("p"), 0);
    EXPECT_EQ(spec->parameter_index("rwm"), -1);
  }
  EXPECT_EQ(find_module(ModuleKind::Condition, 16), nullptr);
}

TEST(ModulesCatalogue, NonFiniteValuesAreNeverAccepted) {
  const ParameterSpec& p = find_module(ModuleKind::Condition, 15)->parameters.at(0);
  EXPECT_FALSE(p.accepts(std::nan("")));
  EXPECT_FALSE(p.accepts(INFINITY));
}

TEST(ModulesCatalogue, FlavourNamesRoundTrip) {
  for (const Flavour f : {Flavour::Chocolate, Flavour::TuttiFrutti, Flavour::Coconut, Flavour::Maple, Flavour::Arlequin})
    EXPECT_EQ(flavour_from_name(flavour_name(f)), f);
  EXPECT_FALSE(flavour_from_name("vanilla").has_value());
}

}  // namespace
}  // namespace sd
