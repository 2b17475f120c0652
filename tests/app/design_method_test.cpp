// The registry of design methods: every name design/methods.hpp lists has an implementation,
// an unknown name is refused as a malformed request (naming the methods it could be), and each
// method rounds its budget its way.
#include <gtest/gtest.h>

#include "app/design_job.hpp"
#include "app/design_method.hpp"
#include "app/errors.hpp"

namespace sd::test {
namespace {

TEST(DesignMethods, EveryListedNameHasItsMethodAndAnUnknownNameIsRefused) {
  for (const design::MethodInfo* info : design::kMethods)
    EXPECT_EQ(&app::design_method(info->name).info(), info) << info->name;
  EXPECT_THROW(app::design_method("simulated-annealing"), app::InvalidRequest);
}

TEST(DesignMethods, TheNamesInMessagesAreEveryMethodOrOnlyTheSearchesOfTheDesignSpace) {
  EXPECT_EQ(design::method_names_text(), "automode, random-search, local-search or evostick");
  EXPECT_EQ(app::search_method_names(), "automode, random-search or local-search");
  try {
    app::search_method("evostick");  // a method, but not one over the modular space
    ADD_FAILURE() << "evostick accepted as a search of the design space";
  } catch (const app::InvalidRequest& e) {
    EXPECT_NE(std::string(e.what()).find("(automode, random-search or local-search)"), std::string::npos) << e.what();
  }
}

TEST(DesignMethods, EachMethodRoundsABudgetItsWay) {
  storage::PlannedDesign evo{"aac", "evostick", 1, std::string(design::kEvoStick.name), "", "", 1500, 0};
  const auto evo_note = app::design_method(evo.method).plan(evo, {"evostick", evo.method, {}, {}});
  EXPECT_EQ(evo.budget, 1000) << "whole generations of 100 networks x 10 runs";
  ASSERT_TRUE(evo_note.has_value());
  EXPECT_NE(evo_note->find("budget 1500 becomes 1000"), std::string::npos) << *evo_note;

  storage::PlannedDesign race{"aac", "alone", 1, std::string(design::kAutoMoDe.name), "", "", 10, 0};
  const experiments::Condition alone{"alone", race.method, {"fsm"}, {"chocolate"}};
  const auto race_note = app::design_method(race.method).plan(race, alone);
  EXPECT_GT(race.budget, 10) << "raised to the optimiser's minimum";
  EXPECT_EQ(race.architectures, "fsm");
  ASSERT_TRUE(race_note.has_value());
  EXPECT_EQ(app::design_method(race.method).plan(race, alone), std::nullopt) << "a budget at the minimum stays";
}

}  // namespace
}  // namespace sd::test
