// The shipped Arlequin weights are the output of `swarmdesign evostick --module NAME` with
// the shipped seed and generations (data/arlequin/README.md). A full regeneration of one
// module takes minutes, so the default test reruns the first two generations of one module
// and checks them against the per-generation record the shipped file carries (best and
// population means, digest of the best network), which an evolution with more generations
// shares bit for bit; the digest chain then ties the shipped weights to the last record.
// SWARMDESIGN_SLOW_TESTS=1 regenerates all six files in full and compares them byte for byte.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "evostick/evolution.hpp"
#include "evostick/module_training.hpp"
#include "evostick/weight_document.hpp"
#include "workflow/swarmdesign_process.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

std::string shipped_text(std::string_view name) {
  std::ifstream in(std::string(::sd::test::source_dir()) + "/data/arlequin/" + std::string(name) + ".json");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ArlequinRegeneration, ShippedFilesRecordTheShippedSettingsAndTheirOwnHistory) {
  for (const auto& module : evostick::module_trainings()) {
    SCOPED_TRACE(std::string(module.name));
    const std::string text = shipped_text(module.name);
    ASSERT_FALSE(text.empty()) << "data/arlequin/" << module.name << ".json is missing";
    const auto doc = nlohmann::json::parse(text);
    EXPECT_EQ(doc["module"], module.id);
    EXPECT_EQ(doc["settings"], evostick::settings_json(evostick::shipped_settings()));
    EXPECT_EQ(doc["produced_by"], evostick::module_command(module, evostick::shipped_settings()));
    ASSERT_EQ(doc["history"].size(), static_cast<std::size_t>(evostick::kShippedGenerations));
    // The weights the binary runs are the file's, and the file's are its last generation's best.
    const arlequin::Weights weights = arlequin::weights_from_json(text, module.name);
    EXPECT_EQ(weights, arlequin::shipped_weights(module.id));
    EXPECT_EQ(doc["weights_digest"], evostick::digest_text(evostick::weight_digest(weights)));
    EXPECT_EQ(doc["history"].back()["best_digest"], doc["weights_digest"]);
    EXPECT_EQ(doc["history"].back()["best_mean"], doc["best_mean"]);
  }
}

TEST(ArlequinRegeneration, TheFirstTwoGenerationsOfThePhototaxisModuleComeOutBitForBit) {
  const auto outcome = test::run_swarmdesign(
      {"evostick", "--module", "phototaxis", "--seed", std::to_string(evostick::kShippedSeed), "--generations", "2",
       "--threads", "2", "--json"},
      "", {});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto rerun = nlohmann::json::parse(outcome.out);
  const auto shipped = nlohmann::json::parse(shipped_text("phototaxis"));
  ASSERT_EQ(rerun["history"].size(), 2u);
  ASSERT_GE(shipped["history"].size(), 2u);
  for (std::size_t g = 0; g < 2; ++g) EXPECT_EQ(rerun["history"][g], shipped["history"][g]) << "generation " << g + 1;
  EXPECT_EQ(rerun["weights_digest"], shipped["history"][1]["best_digest"]);
}

TEST(ArlequinRegeneration, EveryShippedModuleInFull) {
  const char* slow = std::getenv("SWARMDESIGN_SLOW_TESTS");
  if (!slow || std::string(slow) != "1")
    GTEST_SKIP() << "takes minutes per module: run with SWARMDESIGN_SLOW_TESTS=1";
  for (const auto& module : evostick::module_trainings()) {
    const auto outcome = test::run_swarmdesign({"evostick", "--module", std::string(module.name), "--json"}, "", {});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_EQ(outcome.out, shipped_text(module.name)) << module.name << " does not regenerate bit for bit";
  }
}

}  // namespace
}  // namespace sd
