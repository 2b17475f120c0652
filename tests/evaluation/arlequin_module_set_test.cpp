// Which Arlequin module set runs modules 50-55 is a mission field ("arlequin_modules"), so a
// design records it with its mission and an MPI rank rebuilds it: the field is read and
// checked, it enters the digest, naming SwarmDesign's own set changes no score, and
// Demiurge's set runs deterministically.
#include <gtest/gtest.h>

#include <string>

#include "control/config_string.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"

namespace sd {
namespace {

// Set 6's A09 (argos-reference-6.csv): four states, every module kind of transition.
constexpr const char* kFourStates =
    "--fsm-config --nstates 4 --s0 53 --n0 2 --n0x0 0 --c0x0 51 --p0x0 0.43 --n0x1 1 --c0x1 53 --p0x1 1 --w0x1 11.96 "
    "--s1 55 --n1 1 --n1x0 2 --c1x0 53 --p1x0 2 --w1x0 0.68 --s2 55 --n2 2 --n2x0 0 --c2x0 55 --p2x0 0.54 --n2x1 0 "
    "--c2x1 51 --p2x1 0.48 --s3 55 --n3 1 --n3x0 0 --c3x0 55 --p3x0 0.53";

TEST(ArlequinModuleSetField, TheFieldNamesTheSetAndEntersTheDigest) {
  const Mission plain = load_mission("aggregation-xor");
  EXPECT_EQ(plain.arlequin_modules, nullptr);
  const Mission demi = with_arlequin_modules(plain, "demiurge");
  ASSERT_NE(demi.arlequin_modules, nullptr);
  EXPECT_EQ(demi.arlequin_modules->name, "demiurge");
  EXPECT_NE(demi.digest, plain.digest);
  EXPECT_NE(demi.document.find("\"arlequin_modules\": \"demiurge\""), std::string::npos) << "an MPI rank rebuilds it";
  EXPECT_EQ(parse_mission(demi.document, "rank").digest, demi.digest);
  EXPECT_NE(with_arlequin_modules(plain, "swarmdesign").digest, demi.digest);
}

TEST(ArlequinModuleSetField, ABadSetIsOneLineNamingTheField) {
  const Mission plain = load_mission("aac");
  try {
    with_arlequin_modules(plain, "demiurg");
    FAIL() << "accepted";
  } catch (const MissionError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("arlequin_modules: ", 0), 0u) << what;
    EXPECT_NE(what.find("'demiurg'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(ArlequinModuleSetField, NamingSwarmDesignsSetChangesNoScore) {
  const Mission plain = load_mission("aggregation-xor");
  const Mission named = with_arlequin_modules(plain, "swarmdesign");
  const ControlSoftware software = parse_control_software(kFourStates);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_EQ(evaluate(plain, software, seed), evaluate(named, software, seed)) << seed;
}

TEST(ArlequinModuleSetField, DemiurgesSetRunsItsOwnNetworksDeterministically) {
  const Mission plain = load_mission("aac");
  const Mission demi = with_arlequin_modules(plain, "demiurge");
  const ControlSoftware software = parse_control_software(kFourStates);
  const double first = evaluate(demi, software, 4);
  EXPECT_EQ(evaluate(demi, software, 4), first);
  // Demiurge's "stop" moves; SwarmDesign's is all zeros: on AAC a one-state stop scores the
  // robots that start on the black spot, for every tick, only with SwarmDesign's.
  const ControlSoftware stop = parse_control_software("--fsm-config --nstates 1 --s0 51");
  EXPECT_NE(evaluate(demi, stop, 1), evaluate(plain, stop, 1));
}

}  // namespace
}  // namespace sd
