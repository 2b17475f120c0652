#include "design/state.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace sd::design {

namespace {

using nlohmann::json;
constexpr int kFormatVersion = 1;

// JSON has no NaN or Inf: NA is null, infinities are the strings "Inf" / "-Inf".
json number(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  return v;
}
double number(const json& j) {
  if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (j.is_string()) {
    const auto s = j.get<std::string>();
    if (s == "Inf") return std::numeric_limits<double>::infinity();
    if (s == "-Inf") return -std::numeric_limits<double>::infinity();
    throw std::runtime_error("checkpoint: bad number '" + s + "'");
  }
  return j.get<double>();
}
json numbers(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(number(x));
  return a;
}
std::vector<double> numbers(const json& j) {
  std::vector<double> v;
  for (const auto& x : j) v.push_back(number(x));
  return v;
}

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::StartIteration: return "start-iteration";
    case Phase::Racing: return "racing";
    case Phase::Finished: return "finished";
  }
  return "";
}
Phase phase_of(const std::string& s) {
  if (s == "start-iteration") return Phase::StartIteration;
  if (s == "racing") return Phase::Racing;
  if (s == "finished") return Phase::Finished;
  throw std::runtime_error("checkpoint: unknown phase '" + s + "'");
}

json race_to_json(const RaceState& r) {
  return json{{"config_ids", r.config_ids},
              {"head", r.head},
              {"future_begin", r.future_begin},
              {"n_tasks", r.n_tasks},
              {"n_new", r.n_new},
              {"n_old", r.n_old},
              {"has_elite_data", r.has_elite_data},
              {"result_rows", r.results.size()},
              {"alive", r.alive},
              {"rejected", r.rejected},
              {"is_elite", r.is_elite},
              {"elite_safe", r.elite_safe},
              {"no_elimination", r.no_elimination},
              {"next_task", r.next_task},
              {"experiments_used", r.experiments_used},
              {"best", r.best},
              {"finished", r.finished},
              {"stop_reason", r.stop_reason}};
}

RaceState race_from_json(const json& j) {
  RaceState r;
  j.at("config_ids").get_to(r.config_ids);
  j.at("head").get_to(r.head);
  j.at("future_begin").get_to(r.future_begin);
  j.at("n_tasks").get_to(r.n_tasks);
  j.at("n_new").get_to(r.n_new);
  j.at("n_old").get_to(r.n_old);
  j.at("has_elite_data").get_to(r.has_elite_data);
  const auto rows = j.at("result_rows").get<std::size_t>();
  r.results.assign(rows, std::vector<double>(r.config_ids.size(), std::nan("")));  // refilled from the log
  j.at("alive").get_to(r.alive);
  j.at("rejected").get_to(r.rejected);
  j.at("is_elite").get_to(r.is_elite);
  j.at("elite_safe").get_to(r.elite_safe);
  j.at("no_elimination").get_to(r.no_elimination);
  j.at("next_task").get_to(r.next_task);
  j.at("experiments_used").get_to(r.experiments_used);
  j.at("best").get_to(r.best);
  j.at("finished").get_to(r.finished);
  j.at("stop_reason").get_to(r.stop_reason);
  const std::size_t n = r.config_ids.size();
  if (r.alive.size() != n || r.rejected.size() != n || r.is_elite.size() != n)
    throw std::runtime_error("checkpoint: inconsistent race state");
  return r;
}

}  // namespace

json record_to_json(const ConfigRecord& r) { return json::array({r.id, r.parent, numbers(r.config.values)}); }
ConfigRecord config_record_from_json(const json& j) {
  return {j.at(0).get<int>(), j.at(1).get<int>(), Configuration{numbers(j.at(2))}};
}
json record_to_json(const ExperimentRecord& r) {
  return json::array({r.iteration, r.position, r.configuration_id, number(r.cost)});
}
ExperimentRecord experiment_record_from_json(const json& j) {
  return {j.at(0).get<int>(), j.at(1).get<std::size_t>(), j.at(2).get<int>(), number(j.at(3))};
}

json state_to_json(const DesignState& s, bool with_history) {
  json j;
  j["format"] = "swarmdesign-irace-state";
  j["version"] = kFormatVersion;
  j["fingerprint"] = s.fingerprint;
  j["phase"] = phase_name(s.phase);
  j["iteration"] = s.iteration;
  j["nb_iterations"] = s.nb_iterations;
  j["min_survival"] = s.min_survival;
  j["budget"] = s.budget;
  j["remaining_budget"] = s.remaining_budget;
  j["experiments_used"] = s.experiments_used;
  j["current_budget"] = s.current_budget;
  j["nb_configurations"] = s.nb_configurations;
  j["first_race"] = s.first_race;
  j["configuration_count"] = s.configurations.size();
  if (with_history) {
    json confs = json::array();
    for (const ConfigRecord& c : s.configurations.all()) confs.push_back(record_to_json(c));
    j["configurations"] = std::move(confs);
  }
  j["rejected_ids"] = s.rejected_ids;
  json elites = json::array();
  for (const Elite& e : s.elites) elites.push_back({e.id, e.weight});
  j["elites"] = std::move(elites);
  j["all_elites"] = s.all_elites;
  j["soft_restarts"] = s.soft_restarts;
  json model = json::array();
  for (const auto& [id, entry] : s.model.entries) {
    json params = json::array();
    for (const auto& v : entry) params.push_back(numbers(v));
    model.push_back({id, std::move(params)});
  }
  j["model"] = std::move(model);
  j["instances"] = {{"n_instances", s.instances.n_instances()},
                    {"stream_seed", s.instances.stream_seed()},
                    {"sample_instances", s.instances.sample_instances()},
                    {"blocks", s.instances.blocks()}};
  j["positions_seen"] = s.positions_seen;
  j["experiment_count"] = s.experiments.size();
  if (with_history) {
    json log = json::array();
    for (const ExperimentRecord& e : s.experiments) log.push_back(record_to_json(e));
    j["experiments"] = std::move(log);
  }
  j["race"] = s.race ? race_to_json(*s.race) : json(nullptr);
  j["rng"] = {{"s", {s.rng.s[0], s.rng.s[1], s.rng.s[2], s.rng.s[3]}}};
  j["finish_reason"] = s.finish_reason;
  return j;
}

DesignState state_from_json(const json& j, std::optional<History> history) {
  try {
    if (j.value("format", "") != "swarmdesign-irace-state") throw std::runtime_error("not a SwarmDesign design state");
    if (j.at("version").get<int>() != kFormatVersion) throw std::runtime_error("unsupported design-state version");
    DesignState s;
    j.at("fingerprint").get_to(s.fingerprint);
    s.phase = phase_of(j.at("phase").get<std::string>());
    j.at("iteration").get_to(s.iteration);
    j.at("nb_iterations").get_to(s.nb_iterations);
    j.at("min_survival").get_to(s.min_survival);
    j.at("budget").get_to(s.budget);
    j.at("remaining_budget").get_to(s.remaining_budget);
    j.at("experiments_used").get_to(s.experiments_used);
    j.at("current_budget").get_to(s.current_budget);
    j.at("nb_configurations").get_to(s.nb_configurations);
    j.at("first_race").get_to(s.first_race);
    std::vector<ConfigRecord> configurations;
    if (history) {
      configurations = std::move(history->configurations);
    } else {
      for (const auto& c : j.at("configurations")) configurations.push_back(config_record_from_json(c));
    }
    if (configurations.size() != j.at("configuration_count").get<std::size_t>())
      throw std::runtime_error("the configurations do not match the state (" + std::to_string(configurations.size()) +
                               ", expected " + std::to_string(j.at("configuration_count").get<std::size_t>()) + ")");
    for (auto& c : configurations) {
      const int id = s.configurations.add(std::move(c.config), c.parent);
      if (id != c.id) throw std::runtime_error("configuration ids are not consecutive");
    }
    j.at("rejected_ids").get_to(s.rejected_ids);
    for (const auto& e : j.at("elites")) s.elites.push_back({e.at(0).get<int>(), e.at(1).get<double>()});
    j.at("all_elites").get_to(s.all_elites);
    j.at("soft_restarts").get_to(s.soft_restarts);
    for (const auto& m : j.at("model")) {
      auto& entry = s.model.entries[m.at(0).get<int>()];
      for (const auto& v : m.at(1)) entry.push_back(numbers(v));
    }
    const auto& in = j.at("instances");
    s.instances = InstanceList::replay(in.at("n_instances").get<std::size_t>(), in.at("stream_seed").get<std::uint64_t>(),
                                       in.at("sample_instances").get<bool>(), in.at("blocks").get<std::size_t>());
    j.at("positions_seen").get_to(s.positions_seen);
    if (history) {
      s.experiments = std::move(history->experiments);
    } else {
      for (const auto& e : j.at("experiments")) s.experiments.push_back(experiment_record_from_json(e));
    }
    if (s.experiments.size() != j.at("experiment_count").get<std::size_t>())
      throw std::runtime_error("the experiment log does not match the state (" + std::to_string(s.experiments.size()) +
                               " results, expected " + std::to_string(j.at("experiment_count").get<std::size_t>()) + ")");
    if (!j.at("race").is_null()) s.race = race_from_json(j.at("race"));
    const auto& rng = j.at("rng");
    for (int i = 0; i < 4; ++i) s.rng.s[i] = rng.at("s").at(static_cast<std::size_t>(i)).get<std::uint64_t>();
    j.at("finish_reason").get_to(s.finish_reason);
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("malformed design state: ") + e.what());
  }
}

}  // namespace sd::design
