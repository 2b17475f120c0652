// EvoStick's settings and its state file read back: what was written comes back equal, and a
// number no field can hold is refused by name (the weights fuzzer's finding: 2.09e118 as
// "elites" went through nlohmann's get<int>(), which is undefined behaviour).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "evostick/saved_evolution.hpp"
#include "evostick/weight_document.hpp"
#include "refusal.hpp"

namespace {

using nlohmann::json;
using sd::evostick::Settings;

Settings some_settings() {
  Settings s;
  s.population = 12;
  s.evaluations = 3;
  s.elites = 4;
  s.mutation_sigma = 0.5;
  s.generations = 7;
  s.seed = 18446744073709551615ULL;
  return s;
}

std::string refusal(const json& document) {
  return sd::test::refusal_of<std::invalid_argument>([&] { return sd::evostick::settings_from_json(document); });
}

TEST(EvoStickSettings, ComeBackAsWritten) {
  const Settings s = some_settings();
  const Settings back = sd::evostick::settings_from_json(sd::evostick::settings_json(s));
  EXPECT_EQ(back.population, 12);
  EXPECT_EQ(back.evaluations, 3);
  EXPECT_EQ(back.elites, 4);
  EXPECT_EQ(back.generations, 7);
  EXPECT_EQ(back.seed, s.seed);
  EXPECT_EQ(back.mutation_sigma, 0.5);
  EXPECT_EQ(back.mutation_probability, s.mutation_probability);
  EXPECT_EQ(back.weight_bound, s.weight_bound);
}

TEST(EvoStickSettings, ANumberNoFieldCanHoldIsRefusedByName) {
  json doc = sd::evostick::settings_json(some_settings());
  doc["elites"] = 2.09e118;
  EXPECT_EQ(refusal(doc), "settings.elites must be an integer of at most 2147483647");
  doc = sd::evostick::settings_json(some_settings());
  doc["population"] = 4294967296LL;  // would wrap to 0 as an int
  EXPECT_EQ(refusal(doc), "settings.population must be an integer of at most 2147483647");
  doc = sd::evostick::settings_json(some_settings());
  doc["seed"] = -1;
  EXPECT_EQ(refusal(doc), "settings.seed must be an integer of at most 18446744073709551615");
  doc = sd::evostick::settings_json(some_settings());
  doc["mutation_sigma"] = "wide";
  EXPECT_EQ(refusal(doc), "settings.mutation_sigma must be a number");
  doc.erase("generations");
  doc["mutation_sigma"] = 1.0;
  EXPECT_EQ(refusal(doc), "settings.generations is missing");
  EXPECT_EQ(refusal(json::array()), "settings.seed is missing");
}

class SavedEvolutionFile : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::filesystem::temp_directory_path() /
            ("sd-saved-evolution-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
    target_.mission = "aggregation";
    target_.mission_digest = "0x0123456789abcdef";
    target_.settings = some_settings();
    target_.results_version = 3;
    checkpoint_.generation = 2;
    checkpoint_.population.assign(2, sd::arlequin::Weights{});
    checkpoint_.population[1][7] = 1.25;
    checkpoint_.rng = {{1, 2, 3, 18446744073709551615ULL}, 99, 5};
    checkpoint_.result.runs = 72;
    checkpoint_.result.history = {{1, 0.5, 0.25, 0xfeedULL}, {2, 0.75, 0.5, 0xbeefULL}};
    sd::evostick::write_saved_evolution(file_, target_, checkpoint_);
  }
  void TearDown() override { std::filesystem::remove(file_); }

  json document() const { return json::parse(std::ifstream(file_)); }
  void rewrite(const json& doc) const { std::ofstream(file_, std::ios::trunc) << doc.dump(); }
  std::string refusal() const {
    return sd::test::refusal_of<std::runtime_error>([this] { return sd::evostick::read_saved_evolution(file_); });
  }

  std::filesystem::path file_;
  sd::evostick::EvolutionTarget target_;
  sd::evostick::Checkpoint checkpoint_;
};

TEST_F(SavedEvolutionFile, ComesBackAsWritten) {
  const sd::evostick::SavedEvolution saved = sd::evostick::read_saved_evolution(file_);
  EXPECT_EQ(saved.target.mission, target_.mission);
  EXPECT_EQ(saved.target.settings.generations, 7);
  EXPECT_EQ(saved.target.results_version, 3);
  EXPECT_EQ(saved.checkpoint.generation, 2);
  EXPECT_EQ(saved.checkpoint.population, checkpoint_.population);
  EXPECT_EQ(saved.checkpoint.rng.s[3], 18446744073709551615ULL);
  EXPECT_EQ(saved.checkpoint.rng.coarse_bits, 99U);
  EXPECT_EQ(saved.checkpoint.rng.coarse_left, 5);
  EXPECT_EQ(saved.checkpoint.result.runs, 72);
  EXPECT_EQ(saved.checkpoint.result.history, checkpoint_.result.history);
}

TEST_F(SavedEvolutionFile, NumbersNoFieldCanHoldAreADamagedFileNotUndefinedBehaviour) {
  const std::string damaged = file_.string() + " is a damaged EvoStick state file (";
  json doc = document();
  doc["generation"] = 1e300;
  rewrite(doc);
  EXPECT_EQ(refusal(), damaged + "generation is not an integer it can hold)");
  doc = document();
  doc["generation"] = 2;
  doc["rng"]["s"][0] = -5;
  rewrite(doc);
  EXPECT_EQ(refusal(), damaged + "rng.s is not an integer it can hold)");
  doc["rng"]["s"] = {1, 2, 3};
  rewrite(doc);
  EXPECT_EQ(refusal(), damaged + "rng.s is not a list of four words)");
  doc["rng"]["s"] = {1, 2, 3, 4};
  doc["settings"]["elites"] = 2.09e118;
  rewrite(doc);
  EXPECT_EQ(refusal(), damaged + "settings.elites must be an integer of at most 2147483647)");
  doc["settings"]["elites"] = 4;
  doc["history"][0]["best_digest"] = "0x1ffffffffffffffff";  // 65 bits: stoull's out_of_range
  rewrite(doc);
  EXPECT_EQ(refusal(), damaged + "a digest is not 64-bit hexadecimal)");
  doc["history"][0]["best_digest"] = "0xfeed";
  rewrite(doc);
  EXPECT_EQ(refusal(), "(accepted)");
}

}  // namespace
