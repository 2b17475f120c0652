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

TEST(design_DesignSpace, EveryCatalogueModuleIsAValueOfTheSpaceInBothArchitectures) {
  const ParameterSpace space = build_design_space(resolve_design_space({}));
  std::set<std::string> behaviours, conditions;
  for (const auto& m : sd::modules(ModuleKind::Behaviour)) behaviours.insert(std::to_string(m.id));
  for (const auto& m : sd::modules(ModuleKind::Condition)) conditions.insert(std::to_string(m.id));
  for (const char* name : {"S0", "A01"}) {
    const auto& values = space[*space.index_of(name)].values;
    EXPECT_EQ(std::set<std::string>(values.begin(), values.end()), behaviours) << name;
  }
  for (const char* name : {"C0x0", "C00"}) {
    const auto& values = space[*space.index_of(name)].values;
    EXPECT_EQ(std::set<std::string>(values.begin(), values.end()), conditions) << name;
  }
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

std::vector<Flavour> flavours_with_modules(bool with) {
  std::vector<Flavour> out;
  for (Flavour f : {Flavour::Chocolate, Flavour::TuttiFrutti, Flavour::Coconut, Flavour::Maple, Flavour::Arlequin}) {
    bool has = false;
    for (const auto& m : sd::modules(ModuleKind::Behaviour)) has = has || m.flavour() == f;
    if (has == with) out.push_back(f);
  }
  return out;
}

TEST(design_DesignSpace, NoFlagsMeansEverythingThatExists) {
  const DesignSpaceChoice choice = resolve_design_space({});
  EXPECT_EQ(choice.architectures_text(), "fsm,bt");
  EXPECT_EQ(choice.flavours, flavours_with_modules(true));
  EXPECT_TRUE(choice.notes.empty());
  const DesignSpaceChoice explicit_choice = resolve_design_space({true, false, {Flavour::Chocolate}});
  EXPECT_EQ(explicit_choice.flavours_text(), "chocolate");
  EXPECT_EQ(explicit_choice.architectures_text(), "fsm");
  EXPECT_EQ(resolve_design_space({false, true, {Flavour::Maple}}).architectures_text(), "bt");
  EXPECT_EQ(resolve_design_space({true, true, {}}).architectures_text(), "fsm,bt");
}

TEST(design_DesignSpace, FlavoursThatDoNotExistYetAreNamed) {
  for (Flavour f : flavours_with_modules(false)) {
    const std::string error = error_of({false, false, {Flavour::Chocolate, f}});
    EXPECT_NE(error.find("modules are available yet"), std::string::npos) << error;
  }
}

TEST(design_DesignSpace, StoredTextReadsBackAsTheSameRequest) {
  const DesignSpaceChoice choice = resolve_design_space({});
  const DesignSpaceRequest back = request_from_text(choice.architectures_text(), choice.flavours_text());
  EXPECT_TRUE(back.fsm);
  EXPECT_TRUE(back.bt);
  EXPECT_EQ(back.flavours, flavours_with_modules(true));
  EXPECT_THROW(request_from_text("fsm", "vanilla"), std::invalid_argument);
}

TEST(design_DesignSpace, EverySampledConfigurationIsControlSoftwareAndBack) {
  const ParameterSpace space = build_design_space(resolve_design_space({}));
  sd::Rng rng(2024);
  std::set<std::size_t> state_counts, branch_counts;
  for (int k = 0; k < 2000; ++k) {
    const Configuration c = sample_uniform(space, rng);
    const std::string line = space.render(c);
    sd::ControlSoftware software;
    ASSERT_NO_THROW(software = sd::parse_control_software(line)) << line;
    if (software.architecture == sd::Architecture::Fsm) state_counts.insert(software.fsm.states.size());
    else branch_counts.insert(software.bt.nodes.front().children.size());
    // The canonical string of the control software is the same configuration again.
    const std::string canonical = sd::to_config_string(software);
    Configuration back;
    ASSERT_NO_THROW(back = space.parse(canonical)) << canonical;
    EXPECT_EQ(back, c) << line << "\n" << canonical;
  }
  EXPECT_EQ(state_counts, (std::set<std::size_t>{1, 2, 3, 4}));
  EXPECT_EQ(branch_counts, (std::set<std::size_t>{1, 2, 3, 4}));
}
