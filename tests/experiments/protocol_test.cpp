// Protocols as data: the thesis' three experiments, a protocol file read
// back exactly, and every malformed field refused with its path.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiments/protocol.hpp"
#include "refusal.hpp"

namespace sd::experiments {
namespace {

using nlohmann::json;

const MissionPlan& mission(const Protocol& p, const std::string& name) {
  for (const auto& m : p.missions)
    if (m.mission == name) return m;
  throw std::runtime_error("no mission " + name);
}

TEST(experiments_Protocol, ValidationRunsEachFlavourAloneOnItsOwnMissionAndBudget) {
  const Protocol p = builtin_protocol("validation");
  EXPECT_EQ(p.designs, 10);
  EXPECT_EQ(p.assessment_seeds, 20);
  ASSERT_EQ(p.missions.size(), 5u);
  const std::vector<std::tuple<std::string, long long, std::string, std::string>> expected = {
      {"aac", 200000, "chocolate", "fsm"},          {"foraging", 50000, "maple", "bt"},
      {"tutti-aggregation", 100000, "tuttifrutti", "fsm"}, {"grid-exploration", 100000, "coconut", "fsm"},
      {"aggregation-xor", 200000, "arlequin", "fsm"}};
  for (const auto& [name, budget, flavour, architecture] : expected) {
    const MissionPlan& m = mission(p, name);
    EXPECT_EQ(m.budget, budget) << name;
    ASSERT_EQ(m.conditions.size(), 1u);
    EXPECT_EQ(m.conditions[0].flavours, std::vector<std::string>{flavour});
    EXPECT_EQ(m.conditions[0].architectures, std::vector<std::string>{architecture});
  }
}

TEST(experiments_Protocol, CombinationAndArchitecture) {
  const Protocol c = builtin_protocol("combination");
  for (const auto& m : c.missions) {
    ASSERT_EQ(m.conditions.size(), 2u);
    EXPECT_EQ(m.conditions[1].name, "combined");
    EXPECT_EQ(m.conditions[1].flavours.size(), 5u);
    EXPECT_EQ(m.conditions[1].architectures, (std::vector<std::string>{"fsm", "bt"}));
  }
  EXPECT_EQ(condition_names(c), (std::vector<std::string>{"alone", "combined"}));
  const Protocol a = builtin_protocol("architecture", true);
  for (const auto& m : a.missions) {
    EXPECT_EQ(m.budget, 200000);
    ASSERT_EQ(m.conditions.size(), 3u);
    EXPECT_EQ(m.conditions[0].architectures, std::vector<std::string>{"fsm"});
    EXPECT_EQ(m.conditions[1].architectures, std::vector<std::string>{"bt"});
    EXPECT_EQ(m.conditions[2].method, "evostick");
  }
  EXPECT_THROW(builtin_protocol("validaton"), ProtocolError);
}

TEST(experiments_Protocol, MethodsRacesEveryMethodOfTheModularSpaceOnItsFlavourAndOnTheCombinedSpace) {
  const Protocol p = builtin_protocol("methods");
  EXPECT_EQ(condition_names(p), (std::vector<std::string>{"automode", "random-search", "local-search", "automode-combined",
                                                          "random-search-combined", "local-search-combined"}));
  for (const auto& m : p.missions) {
    EXPECT_EQ(m.budget, 20000) << m.mission;
    ASSERT_EQ(m.conditions.size(), 6u);
    EXPECT_EQ(m.conditions[1].method, "random-search");
    EXPECT_EQ(m.conditions[1].flavours.size(), 1u);
    EXPECT_EQ(m.conditions[5].method, "local-search");
    EXPECT_EQ(m.conditions[5].flavours.size(), 5u);
  }
  EXPECT_EQ(to_json(protocol_from_json(to_json(p))), to_json(p));
}

TEST(experiments_Protocol, FileRoundTripAndOverrides) {
  const Protocol p = builtin_protocol("combination", true);
  EXPECT_EQ(to_json(protocol_from_json(to_json(p))), to_json(p));

  ProtocolOverrides o;
  o.missions = std::vector<std::string>{"foraging", "aac"};
  o.designs = 2;
  o.budget_scale = 0.01;
  const Protocol small = with_overrides(p, o);
  ASSERT_EQ(small.missions.size(), 2u);
  EXPECT_EQ(small.missions[0].mission, "foraging");
  EXPECT_EQ(scaled_budget(small, small.missions[0]), 500);
  EXPECT_EQ(scaled_budget(small, small.missions[1]), 2000);
  EXPECT_EQ(small.designs, 2);

  o.missions = std::vector<std::string>{"sca"};
  EXPECT_THROW(with_overrides(p, o), ProtocolError);
}

std::string error_of(const json& document) {
  return sd::test::refusal_of<ProtocolError>([&] { return protocol_from_json(document); });
}

// Found by fuzz_protocol: a number no double holds is nlohmann's out_of_range, which escaped
// the file reader (it caught only parse_error) and ended `experiment --file` in terminate.
TEST(experiments_Protocol, ANumberTooLargeForADoubleIsAProtocolError) {
  try {
    parse_protocol_text(R"({"name":"p","missions":[{"mission":"aac","budget":1e3082001}]})", "p.json");
    ADD_FAILURE() << "accepted";
  } catch (const ProtocolError& e) {
    EXPECT_EQ(std::string(e.what()), "p.json: not a JSON document: number overflow parsing '1e3082001'");
  }
}

TEST(experiments_Protocol, MalformedFieldsAreNamedByTheirPath) {
  const json good = json::parse(R"({"name": "mine", "missions": [{"mission": "aac", "budget": 1000,
      "conditions": [{"name": "a", "architectures": ["fsm"], "flavours": ["chocolate"]}]}]})");
  EXPECT_EQ(error_of(good), "(accepted)");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/name", "name: must be a non-empty string"},
      {"/missions/0/budget", "missions[0].budget: must be an integer"},
      {"/missions/0/conditions/0/flavours/0", "missions[0].conditions[0].flavours[0]: unknown"},
      {"/missions/0/conditions/0/architectures", "missions[0].conditions[0].architectures: must be a non-empty list"},
      {"/missions/0/conditions", "missions[0].conditions: must be a non-empty list"},
  };
  for (const auto& [pointer, message] : cases) {
    json bad = good;
    bad[json::json_pointer(pointer)] = pointer.find("flavours") != std::string::npos ? json("vanilla") : json("x");
    if (pointer == "/name") bad["name"] = "";
    if (pointer.find("architectures") != std::string::npos || pointer == "/missions/0/conditions") bad[json::json_pointer(pointer)] = json::array();
    EXPECT_NE(error_of(bad).find(message), std::string::npos) << error_of(bad);
  }
  json twice = good;
  twice["missions"].push_back(good["missions"][0]);
  EXPECT_NE(error_of(twice).find("missions[1].mission: 'aac' is listed twice"), std::string::npos) << error_of(twice);
  json evo = good;
  evo["missions"][0]["conditions"][0]["method"] = "evostick";
  EXPECT_NE(error_of(evo).find("has no architectures or flavours"), std::string::npos) << error_of(evo);
  json name = good;
  name["name"] = "a/../etc";
  EXPECT_NE(error_of(name).find("may only hold letters"), std::string::npos) << error_of(name);
  name["name"] = "2026-run";  // a name is also a path segment of the web app's report address
  EXPECT_NE(error_of(name).find("must start with a letter"), std::string::npos) << error_of(name);
}

TEST(experiments_Protocol, PseudoRealityIsOptionalAndCheckedFieldByField) {
  const json good = json::parse(R"({"name": "mine", "missions": [{"mission": "aac", "budget": 1000,
      "conditions": [{"name": "a", "architectures": ["fsm"], "flavours": ["chocolate"]}]}],
      "pseudo_reality": {"spec": "sampled-around", "samples": 5}})");
  const Protocol p = protocol_from_json(good);
  ASSERT_TRUE(p.pseudo_reality);
  EXPECT_EQ(p.pseudo_reality->spec, "sampled-around");
  EXPECT_EQ(p.pseudo_reality->samples, 5);
  EXPECT_TRUE(p.pseudo_reality->definition.empty());
  EXPECT_EQ(to_json(protocol_from_json(to_json(p))), to_json(p));
  json defaulted = good;
  defaulted["pseudo_reality"].erase("samples");
  EXPECT_EQ(protocol_from_json(defaulted).pseudo_reality->samples, 20);
  // Without it, the document is the one older versions stored (an experiment resumes by it).
  json without = good;
  without.erase("pseudo_reality");
  EXPECT_FALSE(protocol_from_json(without).pseudo_reality);
  EXPECT_FALSE(to_json(protocol_from_json(without)).contains("pseudo_reality"));

  const std::vector<std::pair<json, std::string>> cases = {
      {json("sampled-around"), "protocol: pseudo_reality: must be an object"},
      {json::object(), "protocol: pseudo_reality.spec: is missing"},
      {{{"spec", ""}}, "protocol: pseudo_reality.spec: must be a non-empty string"},
      {{{"spec", "x"}, {"samples", 0}}, "protocol: pseudo_reality.samples: must be between 1 and 1000, not 0"},
      {{{"spec", "x"}, {"samples", "20"}}, "protocol: pseudo_reality.samples: must be an integer"},
      {{{"spec", "x"}, {"sample", 2}}, "protocol: pseudo_reality.sample: unknown field"},
      {{{"spec", "x"}, {"definition", 3}}, "protocol: pseudo_reality.definition: must be an object (a pseudo-reality specification)"},
  };
  for (const auto& [value, message] : cases) {
    json bad = good;
    bad["pseudo_reality"] = value;
    EXPECT_EQ(error_of(bad), message);
  }

  // The command line adds one to any protocol, or changes its samples.
  ProtocolOverrides o;
  o.pseudo_reality = "iridia-transfer";
  o.pseudo_reality_samples = 3;
  const Protocol added = with_overrides(builtin_protocol("validation"), o);
  ASSERT_TRUE(added.pseudo_reality);
  EXPECT_EQ(added.pseudo_reality->spec, "iridia-transfer");
  EXPECT_EQ(added.pseudo_reality->samples, 3);
  ProtocolOverrides only_samples;
  only_samples.pseudo_reality_samples = 3;
  EXPECT_EQ(sd::test::refusal_of<ProtocolError>([&] { return with_overrides(builtin_protocol("validation"), only_samples); }),
            "--pseudo-reality-samples: the protocol has no pseudo_reality; name one with --pseudo-reality");
}

}  // namespace
}  // namespace sd::experiments
