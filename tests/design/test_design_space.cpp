// The design space read from the module catalogue, and the architecture / flavour flags.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "control/config_string.hpp"
#include "core/rng.hpp"
#include "design/design_space.hpp"
#include "design/sampling.hpp"

using namespace sd::design;
using sd::Flavour;
using sd::ModuleKind;

namespace {

std::string error_of(const DesignSpaceRequest& request) {
  try {
    resolve_design_space(request);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(design_DesignSpace, EveryCatalogueModuleOfTheFlavourIsAValueOfTheSpace) {
  const ParameterSpace space = build_design_space(resolve_design_space({}));
  std::set<std::string> behaviours, conditions;
  for (const auto& m : sd::modules(ModuleKind::Behaviour))
    if (m.flavour() == Flavour::Chocolate) behaviours.insert(std::to_string(m.id));
  for (const auto& m : sd::modules(ModuleKind::Condition))
    if (m.flavour() == Flavour::Chocolate) conditions.insert(std::to_string(m.id));
  const auto& s0 = space[*space.index_of("S0")].values;
  const auto& c0 = space[*space.index_of("C0x0")].values;
  EXPECT_EQ(std::set<std::string>(s0.begin(), s0.end()), behaviours);
  EXPECT_EQ(std::set<std::string>(c0.begin(), c0.end()), conditions);
  // Every parameter of every module has its irace parameter, domain taken from the catalogue.
  for (const auto& m : sd::modules(ModuleKind::Behaviour))
    for (const auto& p : m.parameters) {
      bool found = false;
      for (const Parameter& q : space.parameters())
        if (q.switch_ == "--" + p.token + "0 ") {
          found = true;
          EXPECT_EQ(q.lower.constant, p.min) << p.token;
          EXPECT_EQ(q.upper.constant, p.max) << p.token;
        }
      EXPECT_TRUE(found) << m.name << " " << p.token;
    }
}

TEST(design_DesignSpace, NoFlagsMeansEverythingThatExists) {
  const DesignSpaceChoice choice = resolve_design_space({});
  EXPECT_EQ(choice.architectures_text(), "fsm");
  EXPECT_EQ(choice.flavours_text(), "chocolate");
  EXPECT_TRUE(choice.notes.empty());
  const DesignSpaceChoice explicit_choice = resolve_design_space({true, false, {Flavour::Chocolate}});
  EXPECT_EQ(explicit_choice.flavours_text(), "chocolate");
}

TEST(design_DesignSpace, FlavoursAndArchitecturesThatDoNotExistYetAreNamed) {
  EXPECT_EQ(error_of({false, false, {Flavour::Maple}}), "no Maple modules are available yet");
  EXPECT_EQ(error_of({false, false, {Flavour::Chocolate, Flavour::Coconut}}), "no Coconut modules are available yet");
  EXPECT_NE(error_of({false, true, {}}).find("behaviour trees are not available yet"), std::string::npos);
  // With --fsm beside it, --bt leaves a note and the FSM space is used.
  const DesignSpaceChoice both = resolve_design_space({true, true, {}});
  EXPECT_EQ(both.architectures_text(), "fsm");
  ASSERT_EQ(both.notes.size(), 1u);
  EXPECT_NE(both.notes[0].find("behaviour trees"), std::string::npos);
}

TEST(design_DesignSpace, StoredTextReadsBackAsTheSameRequest) {
  const DesignSpaceChoice choice = resolve_design_space({});
  const DesignSpaceRequest back = request_from_text(choice.architectures_text(), choice.flavours_text());
  EXPECT_TRUE(back.fsm);
  EXPECT_FALSE(back.bt);
  EXPECT_EQ(back.flavours, std::vector<Flavour>{Flavour::Chocolate});
  EXPECT_THROW(request_from_text("fsm", "vanilla"), std::invalid_argument);
}

TEST(design_DesignSpace, EverySampledConfigurationIsControlSoftwareAndBack) {
  const ParameterSpace space = build_design_space(resolve_design_space({}));
  sd::Rng rng(2024);
  std::set<std::size_t> state_counts;
  for (int k = 0; k < 2000; ++k) {
    const Configuration c = sample_uniform(space, rng);
    const std::string line = space.render(c);
    sd::ControlSoftware software;
    ASSERT_NO_THROW(software = sd::parse_control_software(line)) << line;
    state_counts.insert(software.fsm.states.size());
    // The canonical string of the control software is the same configuration again.
    const std::string canonical = sd::to_config_string(software);
    Configuration back;
    ASSERT_NO_THROW(back = space.parse(canonical)) << canonical;
    EXPECT_EQ(back, c) << line << "\n" << canonical;
  }
  EXPECT_EQ(state_counts, (std::set<std::size_t>{1, 2, 3, 4}));
}
