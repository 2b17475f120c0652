// A walk over the whole catalogue: every module carries its law, its parameters are named and
// their domains are sound, and each module runs the same on a small swarm every time (and as it
// ran before the laws moved into the catalogue: the fingerprints below were taken from the
// switch-based dispatch). A module without a law, or a law that reads a parameter its module
// lacks, is refused when the table is built.
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>

#include "module_walk.hpp"

namespace sd {
namespace {

TEST(ModuleLaws, EveryModuleHasItsLawAndNamedParametersInTheirDomains) {
  int modules_walked = 0;
  for (const ModuleKind kind : {ModuleKind::Behaviour, ModuleKind::Condition}) {
    for (const ModuleSpec& m : modules(kind)) {
      SCOPED_TRACE(m.id);
      ++modules_walked;
      EXPECT_EQ(m.kind, kind);
      if (kind == ModuleKind::Behaviour) {
        EXPECT_NE(m.behaviour.run, nullptr);
        EXPECT_EQ(m.condition.check, nullptr);
      } else {
        EXPECT_NE(m.condition.check, nullptr);
        EXPECT_EQ(m.behaviour.run, nullptr);
      }
      EXPECT_EQ(&module_to_run(kind, m.id), &m) << "a control step finds the catalogue's own entry";
      const ParameterNames& reads = kind == ModuleKind::Behaviour ? m.behaviour.reads : m.condition.reads;
      std::map<std::string, int> seen;
      for (std::size_t p = 0; p < m.parameters.size(); ++p) {
        const ParameterSpec& ps = m.parameters[p];
        EXPECT_FALSE(ps.token.empty());
        EXPECT_EQ(++seen[ps.token], 1) << ps.token << " named twice";
        EXPECT_FALSE(ps.meaning.empty()) << ps.token;
        EXPECT_LE(ps.min, ps.max) << ps.token;
        EXPECT_TRUE(ps.accepts(ps.min)) << ps.token;
        EXPECT_TRUE(ps.accepts(ps.max)) << ps.token;
        for (const double v : ps.values) EXPECT_TRUE(ps.accepts(v)) << ps.token;
        // The law reads this parameter under its name, at this index.
        bool read = false;
        for (std::size_t r = 0; r < reads.size(); ++r)
          if (reads[r] == ps.token) {
            read = true;
            EXPECT_EQ(m.law_index[r], static_cast<std::int8_t>(p)) << ps.token;
          }
        EXPECT_TRUE(read) << ps.token << " is not read by the law";
      }
    }
  }
  EXPECT_EQ(modules_walked, 30 + 31);
}

TEST(ModuleLaws, EveryModuleRunsTheSameOnASmallSwarmAsBefore) {
  // walk_fingerprint(kind, walk_instance(spec, variant), seed 7) for variants 0, 1 and 2, as the
  // switch-based run_behaviour and check_condition of main (0d5210c) computed them.
  const std::map<std::pair<int, int>, std::uint64_t> before = {
#include "module_walk_fingerprints.inc"
  };
  for (const ModuleKind kind : {ModuleKind::Behaviour, ModuleKind::Condition})
    for (const ModuleSpec& m : modules(kind))
      for (int variant = 0; variant < 3; ++variant) {
        SCOPED_TRACE(testing::Message() << "module " << m.id << " variant " << variant);
        const ModuleInstance instance = test::walk_instance(m, variant);
        const std::uint64_t first = test::walk_fingerprint(kind, instance, 7);
        EXPECT_EQ(first, test::walk_fingerprint(kind, instance, 7)) << "a second run differs";
        EXPECT_NE(first, test::walk_fingerprint(kind, instance, 8)) << "the seed changes nothing";
        const int key = (kind == ModuleKind::Behaviour ? 0 : 100) + m.id;
        const auto expected = before.find({key, variant});
        ASSERT_NE(expected, before.end());
        EXPECT_EQ(first, expected->second);
      }
}

TEST(ModuleLaws, BehavioursStayWithinTheWheelsRange) {
  for (const ModuleSpec& m : modules(ModuleKind::Behaviour))
    for (int variant = 0; variant < 3; ++variant) {
      const ModuleInstance instance = test::walk_instance(m, variant);
      prepare_behaviour(instance);
      SwarmState s;
      s.resize(3, 0);
      Rng world(3), rng(4);
      ReferenceModel rm;
      rm.reset();
      BehaviourMemory memory;
      for (int t = 0; t < 30; ++t) {
        test::fake_sensing(s, world);
        rm.update(s, 0);
        const Actuation a = run_behaviour(instance, memory, rm, rng);
        EXPECT_LE(std::abs(a.left_cm), 12.0 + 1e-9) << m.id;
        EXPECT_LE(std::abs(a.right_cm), 12.0 + 1e-9) << m.id;
      }
    }
}

ModuleSpec lone(ModuleKind kind, int id) {
  ModuleSpec m{};
  m.id = id;
  m.kind = kind;
  m.name = "Lone";
  return m;
}

ModuleSpec lone_behaviour(BehaviourLaw law, std::vector<ParameterSpec> parameters = {}) {
  ModuleSpec m = lone(ModuleKind::Behaviour, 19);
  m.parameters = std::move(parameters);
  m.behaviour = law;
  return m;
}

std::string refusal(std::vector<ModuleSpec> table) {
  try {
    with_resolved_laws(std::move(table));
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(ModuleLaws, ATableWithAMissingOrMismatchedLawIsRefusedUpFront) {
  const BehaviourLaw& stop = find_module(ModuleKind::Behaviour, 11)->behaviour;
  EXPECT_EQ(refusal({lone_behaviour(BehaviourLaw{})}), "module 19 (Lone) has no behaviour law");
  ParameterSpec rwm = find_module(ModuleKind::Behaviour, 10)->parameters[0];
  EXPECT_EQ(refusal({lone_behaviour(stop, {rwm})}), "module 19 (Lone) has a parameter its law does not read");
  BehaviourLaw reads_att = stop;
  reads_att.reads = {"att"};
  EXPECT_EQ(refusal({lone_behaviour(reads_att, {rwm})}), "module 19 (Lone) has a law that reads a parameter it lacks: att");
  EXPECT_EQ(refusal({lone(ModuleKind::Condition, 18)}), "module 18 (Lone) has no condition law");
  EXPECT_EQ(refusal({lone_behaviour(stop), lone_behaviour(stop)}), "module 19 (Lone) is listed twice");
  BehaviourLaw reads_rwm = stop;
  reads_rwm.reads = {"rwm"};
  const std::vector<ModuleSpec> resolved = with_resolved_laws({lone_behaviour(reads_rwm, {rwm})});
  EXPECT_EQ(resolved.at(0).law_index[0], 0);
}

TEST(ModuleLaws, AnIdTheCatalogueLacksIsNeverASilentStop) {
  ModuleInstance unknown;
  unknown.id = 16;
  EXPECT_THROW(prepare_behaviour(unknown), std::invalid_argument);
  SwarmState s;
  s.resize(2, 0);
  ReferenceModel rm;
  rm.reset();
  Rng rng(1);
  BehaviourMemory memory;
  EXPECT_THROW(run_behaviour(unknown, memory, rm, rng), std::invalid_argument);
  EXPECT_THROW(check_condition(unknown, rm, rng), std::invalid_argument);
  unknown.id = 1000;
  EXPECT_THROW(run_behaviour(unknown, memory, rm, rng), std::invalid_argument);
  unknown.id = -3;
  EXPECT_THROW(check_condition(unknown, rm, rng), std::invalid_argument);
}

}  // namespace
}  // namespace sd
