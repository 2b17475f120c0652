// Arlequin module sets and Demiurge's machinery (AmmarHsn/Demiurge 0179ecf8's
// AutoMoDeBehaviourGenomeHarlequin on demiurge-epuck-dao bad4dba's ReferenceModel3Dot0): the
// built-in sets hold the files of data/, a folder set reads the same, a bad name fails in one
// line, and the 25 inputs follow Demiurge (GetGroundInput's 10-step filter, real-robot grey
// samples drawn from the robot's generator, the RAB buffer emptied on a state's entry step).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "module_test_helpers.hpp"
#include "modules/arlequin_demiurge.hpp"
#include "modules/arlequin_module_set.hpp"
#include "robot/reference_model_test_helpers.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

using arlequin::Inputs;
using arlequin::Machinery;
using arlequin::ModuleSet;

const std::string kDataDir = std::string(::sd::test::source_dir()) + "/data/arlequin-demiurge";

// ---- sets ------------------------------------------------------------------------------

TEST(ArlequinModuleSets, BuiltInSetsHoldTheirDataFilesAndMachinery) {
  const ModuleSet* sd_set = arlequin::builtin_module_set("swarmdesign");
  const ModuleSet* demi = arlequin::builtin_module_set("demiurge");
  ASSERT_NE(sd_set, nullptr);
  ASSERT_NE(demi, nullptr);
  EXPECT_EQ(sd_set->machinery, Machinery::SwarmDesign);
  EXPECT_EQ(demi->machinery, Machinery::Demiurge);
  for (int id = 50; id <= 55; ++id) EXPECT_EQ(sd_set->of(id), arlequin::shipped_weights(id)) << id;
  // attraction.json's first and last weights of each row, as the genome's text gives them.
  EXPECT_EQ(demi->of(54)[0], -1.85874);
  EXPECT_EQ(demi->of(54)[24], -1.33918);
  EXPECT_EQ(demi->of(54)[25], 0.651305);
  EXPECT_EQ(demi->of(54)[49], -0.495758);
  EXPECT_NE(demi->digest, sd_set->digest);
  EXPECT_EQ(arlequin::builtin_module_set("chocolate"), nullptr);
}

TEST(ArlequinModuleSets, TheDemiurgeFolderReadsAsTheBuiltInSet) {
  const auto folder = arlequin::load_module_set(kDataDir);
  EXPECT_EQ(folder->machinery, Machinery::Demiurge);  // from its module-set.json
  EXPECT_EQ(folder->weights, arlequin::builtin_module_set("demiurge")->weights);
  EXPECT_EQ(folder->digest, arlequin::builtin_module_set("demiurge")->digest);
}

TEST(ArlequinModuleSets, AFolderWithoutProfileIsSwarmDesignMachineryAndBadSetsFailInOneLine) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sd-arlequin-set-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const auto name : arlequin::kModuleNames)
    std::filesystem::copy_file(kDataDir + "/" + std::string(name) + ".json", dir / (std::string(name) + ".json"));
  const auto set = arlequin::load_module_set(dir.string());
  EXPECT_EQ(set->machinery, Machinery::SwarmDesign);
  EXPECT_EQ(set->weights, arlequin::builtin_module_set("demiurge")->weights);
  EXPECT_NE(set->digest, arlequin::builtin_module_set("demiurge")->digest) << "the machinery is part of the digest";

  const auto message_of = [](const std::string& name) {
    try {
      arlequin::load_module_set(name);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string unknown = message_of("demiurg");
  EXPECT_NE(unknown.find("'demiurg' is neither swarmdesign, demiurge nor a folder"), std::string::npos) << unknown;
  std::filesystem::remove(dir / "repulsion.json");
  const std::string missing = message_of(dir.string());
  EXPECT_NE(missing.find("repulsion.json"), std::string::npos) << missing;
  std::ofstream(dir / "repulsion.json") << R"({"weights": {"left": [1, 2], "right": []}})";
  const std::string short_row = message_of(dir.string());
  EXPECT_NE(short_row.find("weights.left must be an array of 25 numbers"), std::string::npos) << short_row;
  std::filesystem::copy_file(kDataDir + "/repulsion.json", dir / "repulsion.json",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "module-set.json") << R"({"machinery": "neat"})";
  const std::string profile = message_of(dir.string());
  EXPECT_NE(profile.find("\"machinery\" must be \"swarmdesign\" or \"demiurge\""), std::string::npos) << profile;
  for (const std::string& m : {unknown, missing, short_row, profile}) EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  std::filesystem::remove_all(dir);
}

TEST(ArlequinModuleSets, GreySamplesAreDemiurgesTablesAsFloat) {
  const auto& s = arlequin::demiurge::grey_samples();
  EXPECT_EQ(s.left[0], 0.339228F);  // row 0 of grey-samples.csv
  EXPECT_EQ(s.centre[0], 0.23196F);
  EXPECT_EQ(s.right[1], 0.899225F);
  const auto mean = [](const auto& t) { return std::accumulate(t.begin(), t.end(), 0.0) / static_cast<double>(t.size()); };
  EXPECT_NEAR(mean(s.left), 0.407, 0.001);  // the statistics the data's README gives
  EXPECT_NEAR(mean(s.centre), 0.342, 0.001);
  EXPECT_NEAR(mean(s.right), 0.423, 0.001);
}

// ---- Demiurge's inputs -------------------------------------------------------------------

class DemiurgeInputs : public testing::Test {
 protected:
  Inputs step(int steps_since_entry, const std::vector<test::Packet>& packets = {}) {
    test::set_packets(swarm, 0, packets);
    rm.update(swarm, 0);
    return arlequin::demiurge::encode_inputs(rm, steps_since_entry, rng);
  }
  SwarmState swarm = test::silent_swarm(4);
  ReferenceModel rm;
  Rng rng{7};
};

TEST_F(DemiurgeInputs, GreyFloorDrawsOneRealRobotSamplePerSensorLeftCentreRight) {
  swarm.ground[0] = {0.5, 0.5, 0.5};
  Rng expected = rng;
  const Inputs x = step(20);
  const auto& s = arlequin::demiurge::grey_samples();
  EXPECT_EQ(x[16], static_cast<double>(s.left[expected.uniform_int(0, 4204)]));
  EXPECT_EQ(x[17], static_cast<double>(s.centre[expected.uniform_int(0, 4204)]));
  EXPECT_EQ(x[18], static_cast<double>(s.right[expected.uniform_int(0, 4204)]));
  EXPECT_TRUE(test::same_rng_state(rng, expected)) << "three draws, no more";
}

TEST_F(DemiurgeInputs, GroundInputsFilterOverTenStepsWithThresholdsThreeAndEightyFiveHundredths) {
  // Black (0.02 < 0.03): more than 10 of 30 readings needs 4 black steps after 6 grey ones.
  swarm.ground[0] = {0.5, 0.5, 0.5};
  for (int k = 0; k < 6; ++k) step(20);
  swarm.ground[0] = {0.02, 0.02, 0.02};
  for (int k = 0; k < 3; ++k) {
    step(20);
    EXPECT_EQ(rm.ground_input_demiurge, 0.5) << k;
  }
  Rng before = rng;
  Inputs x = step(20);
  EXPECT_EQ(x[16], 0.0);
  EXPECT_EQ(x[17], 0.0);
  EXPECT_EQ(x[18], 0.0);
  EXPECT_TRUE(test::same_rng_state(rng, before)) << "no draw off grey";
  // White needs readings above 0.85 (0.9 counts; RM3.0's floor conditions would need > 0.97)
  // and no black majority: the 7th step of 0.9 pushes the first black step out of the window.
  swarm.ground[0] = {0.9, 0.9, 0.9};
  for (int k = 0; k < 6; ++k) step(20);
  EXPECT_EQ(rm.ground_input_demiurge, 0.0);
  x = step(20);
  EXPECT_EQ(x[16], 1.0);
  EXPECT_EQ(x[18], 1.0);
  EXPECT_EQ(rm.ground_input_demiurge, 1.0);
  EXPECT_EQ(rm.ground_demiurge, 0.5) << "the floor conditions' filter is another one";
}

TEST_F(DemiurgeInputs, TheRabBufferHoldsOnlyMessagesSinceTheStateWasEntered) {
  // Messages straight ahead at 10 cm on two steps; the state is entered on the second.
  step(5, {{10.0, 0.0, 1}});
  Inputs x = step(0, {{30.0, kPi / 2.0, 2}});
  for (std::size_t k = 20; k < 24; ++k) EXPECT_EQ(x[k], 0.0) << "emptied at the entry step, its messages too";
  EXPECT_NEAR(x[19], 0.4621171572600098, 1e-15) << "the neighbour count is this step's";
  x = step(1, {{20.0, kPi / 2.0, 2}});  // only this step's message: (0, 20) cm
  EXPECT_NEAR(x[20], 20.0 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(x[21], 20.0 * std::sqrt(0.5), 1e-12);
  x = step(2, {{10.0, 0.0, 1}});  // mean of (0, 20) and (10, 0): (5, 10)
  EXPECT_NEAR(x[20], 10.606601717798213, 1e-12);
  EXPECT_NEAR(x[21], 3.535533905932738, 1e-12);
  // Eleven or more steps after entry the buffer is the whole 11-step window, summed as
  // SwarmDesign's machinery sums it.
  for (int k = 0; k < 8; ++k) step(3 + k);
  int partial = 0, whole = 0;
  const Vec2 a = rm.recent_neighbour_position_sum(11, partial);
  const Vec2 b = rm.neighbour_position_sum();
  whole = rm.buffered_messages();
  EXPECT_EQ(partial, whole);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
}

TEST(ArlequinModuleSets, DemiurgeDriveCountsStepsInStateAndSwarmDesignDriveIsTheShippedOne) {
  SwarmState swarm = test::silent_swarm(2);
  swarm.ground[0] = {0.0, 0.0, 0.0};
  ReferenceModel rm;
  rm.update(swarm, 0);
  BehaviourMemory memory;
  Rng rng(3);
  const Actuation shipped = arlequin::builtin_module_set("swarmdesign")->drive(54, memory, rm, rng);
  const Actuation direct = arlequin::drive(arlequin::shipped_weights(54), rm);
  EXPECT_EQ(shipped.left_cm, direct.left_cm);
  EXPECT_EQ(shipped.right_cm, direct.right_cm);
  EXPECT_EQ(memory.steps_in_state, 0) << "SwarmDesign's machinery keeps no count";
  const ModuleSet& demi = *arlequin::builtin_module_set("demiurge");
  for (int k = 0; k < 15; ++k) demi.drive(50, memory, rm, rng);
  EXPECT_EQ(memory.steps_in_state, ReferenceModel::kRabBufferSteps) << "capped once the buffer is whole";
}

}  // namespace
}  // namespace sd
