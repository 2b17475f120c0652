#include "design/state.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>

#include "core/json_integer.hpp"

namespace sd::design {

namespace {

using nlohmann::json;
constexpr int kFormatVersion = 1;

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};

/// A value of the state read into `out`; an integer (alone or in a list) only when it is one
/// `out` can hold: a damaged state must fail in one line, and nlohmann's conversion of 1e300
/// to int is undefined behaviour.
template <class T>
void read_value(const json& value, const std::string& what, T& out) {
  if constexpr (std::is_same_v<T, char>) {  // flags (alive, rejected); std::in_range takes no plain char
    out = static_cast<char>(checked_json_integer<signed char>(value, what));
  } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    out = checked_json_integer<T>(value, what);
  } else if constexpr (IsVector<T>::value) {
    if (!value.is_array()) throw std::runtime_error(what + " is not a list");
    out.clear();
    for (const json& item : value) {
      typename T::value_type element{};
      read_value(item, what + "[]", element);
      out.push_back(element);
    }
  } else {
    value.get_to(out);
  }
}
template <class T>
void read_field(const json& object, const char* key, T& out) {
  read_value(object.at(key), std::string("design state: ") + key, out);
}
template <class T>
T integer_at(const json& object, const char* key) {
  return checked_json_integer<T>(object.at(key), std::string("design state: ") + key);
}

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
  read_field(j, "config_ids", r.config_ids);
  read_field(j, "head", r.head);
  read_field(j, "future_begin", r.future_begin);
  read_field(j, "n_tasks", r.n_tasks);
  read_field(j, "n_new", r.n_new);
  read_field(j, "n_old", r.n_old);
  read_field(j, "has_elite_data", r.has_elite_data);
  const auto rows = integer_at<std::size_t>(j, "result_rows");
  r.results.assign(rows, std::vector<double>(r.config_ids.size(), std::nan("")));  // refilled from the log
  read_field(j, "alive", r.alive);
  read_field(j, "rejected", r.rejected);
  read_field(j, "is_elite", r.is_elite);
  read_field(j, "elite_safe", r.elite_safe);
  read_field(j, "no_elimination", r.no_elimination);
  read_field(j, "next_task", r.next_task);
  read_field(j, "experiments_used", r.experiments_used);
  read_field(j, "best", r.best);
  read_field(j, "finished", r.finished);
  read_field(j, "stop_reason", r.stop_reason);
  const std::size_t n = r.config_ids.size();
  if (r.alive.size() != n || r.rejected.size() != n || r.is_elite.size() != n)
    throw std::runtime_error("checkpoint: inconsistent race state");
  return r;
}

}  // namespace

json record_to_json(const ConfigRecord& r) { return json::array({r.id, r.parent, numbers(r.config.values)}); }
ConfigRecord config_record_from_json(const json& j) {
  return {checked_json_integer<int>(j.at(0), "design state: configuration id"), checked_json_integer<int>(j.at(1), "design state: configuration parent"),
          Configuration{numbers(j.at(2))}};
}
json record_to_json(const ExperimentRecord& r) {
  return json::array({r.iteration, r.position, r.configuration_id, number(r.cost)});
}
ExperimentRecord experiment_record_from_json(const json& j) {
  return {checked_json_integer<int>(j.at(0), "design state: experiment iteration"), checked_json_integer<std::size_t>(j.at(1), "design state: experiment position"),
          checked_json_integer<int>(j.at(2), "design state: experiment configuration"), number(j.at(3))};
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
    if (integer_at<int>(j, "version") != kFormatVersion) throw std::runtime_error("unsupported design-state version");
    DesignState s;
    read_field(j, "fingerprint", s.fingerprint);
    s.phase = phase_of(j.at("phase").get<std::string>());
    read_field(j, "iteration", s.iteration);
    read_field(j, "nb_iterations", s.nb_iterations);
    read_field(j, "min_survival", s.min_survival);
    read_field(j, "budget", s.budget);
    read_field(j, "remaining_budget", s.remaining_budget);
    read_field(j, "experiments_used", s.experiments_used);
    read_field(j, "current_budget", s.current_budget);
    read_field(j, "nb_configurations", s.nb_configurations);
    read_field(j, "first_race", s.first_race);
    std::vector<ConfigRecord> configurations;
    if (history) {
      configurations = std::move(history->configurations);
    } else {
      for (const auto& c : j.at("configurations")) configurations.push_back(config_record_from_json(c));
    }
    if (configurations.size() != integer_at<std::size_t>(j, "configuration_count"))
      throw std::runtime_error("the configurations do not match the state (" + std::to_string(configurations.size()) +
                               ", expected " + std::to_string(integer_at<std::size_t>(j, "configuration_count")) + ")");
    for (auto& c : configurations) {
      const int id = s.configurations.add(std::move(c.config), c.parent);
      if (id != c.id) throw std::runtime_error("configuration ids are not consecutive");
    }
    read_field(j, "rejected_ids", s.rejected_ids);
    for (const auto& e : j.at("elites")) s.elites.push_back({checked_json_integer<int>(e.at(0), "design state: elite id"), e.at(1).get<double>()});
    read_field(j, "all_elites", s.all_elites);
    read_field(j, "soft_restarts", s.soft_restarts);
    for (const auto& m : j.at("model")) {
      auto& entry = s.model.entries[checked_json_integer<int>(m.at(0), "design state: model entry")];
      for (const auto& v : m.at(1)) entry.push_back(numbers(v));
    }
    const auto& in = j.at("instances");
    s.instances = InstanceList::replay(integer_at<std::size_t>(in, "n_instances"), integer_at<std::uint64_t>(in, "stream_seed"),
                                       in.at("sample_instances").get<bool>(), integer_at<std::size_t>(in, "blocks"));
    read_field(j, "positions_seen", s.positions_seen);
    if (history) {
      s.experiments = std::move(history->experiments);
    } else {
      for (const auto& e : j.at("experiments")) s.experiments.push_back(experiment_record_from_json(e));
    }
    if (s.experiments.size() != integer_at<std::size_t>(j, "experiment_count"))
      throw std::runtime_error("the experiment log does not match the state (" + std::to_string(s.experiments.size()) +
                               " results, expected " + std::to_string(integer_at<std::size_t>(j, "experiment_count")) + ")");
    if (!j.at("race").is_null()) s.race = race_from_json(j.at("race"));
    const auto& rng = j.at("rng");
    for (int i = 0; i < 4; ++i) s.rng.s[i] = checked_json_integer<std::uint64_t>(rng.at("s").at(static_cast<std::size_t>(i)), "design state: rng.s");
    read_field(j, "finish_reason", s.finish_reason);
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("malformed design state: ") + e.what());
  }
}

}  // namespace sd::design
