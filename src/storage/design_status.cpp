#include "storage/design_status.hpp"

#include <nlohmann/json.hpp>

#include "core/json_integer.hpp"
#include "storage/design_store.hpp"

namespace sd::storage {

namespace {

using nlohmann::json;

/// Holds a read transaction for the reader's lifetime: one consistent snapshot.
class Snapshot {
 public:
  explicit Snapshot(const std::filesystem::path& folder) : store_(DesignStore::open(folder)) {
    store_.database().execute("BEGIN");
  }
  ~Snapshot() {
    try {
      store_.database().execute("COMMIT");
    } catch (const DatabaseError&) {
    }
  }
  Snapshot(const Snapshot&) = delete;
  Snapshot& operator=(const Snapshot&) = delete;
  Database& db() { return store_.database(); }
  double score(double cost) const { return store_.meta().direction == "minimize" ? cost : -cost; }
  std::int64_t budget() const { return store_.meta().budget; }

 private:
  DesignStore store_;
};

/// An integer of the saved design state, range-checked (a damaged state fails in one line).
template <class Int>
Int state_integer(const json& value, const char* what) {
  return checked_json_integer<Int>(value, std::string("design state: ") + what);
}

std::int64_t count(Database& db, const std::string& sql) {
  auto q = db.prepare(sql);
  q.step();
  return q.integer(0);
}

ConfigurationScore configuration_score(Snapshot& s, int id, std::optional<int> iteration = std::nullopt) {
  ConfigurationScore c;
  c.id = id;
  auto line = s.db().prepare("SELECT command_line FROM configurations WHERE id = ?");
  line.bind(1, id);
  if (line.step()) c.command_line = line.text(0);
  auto runs = s.db().prepare(iteration ? "SELECT avg(cost), count(*) FROM experiments WHERE configuration_id = ? AND iteration = ?"
                                       : "SELECT avg(cost), count(*) FROM experiments WHERE configuration_id = ?");
  runs.bind(1, id);
  if (iteration) runs.bind(2, *iteration);
  runs.step();
  c.runs = runs.integer(1);
  if (c.runs > 0 && !runs.is_null(0)) c.mean_score = s.score(runs.real(0));
  return c;
}

}  // namespace

DesignProgress read_design_progress(const std::filesystem::path& folder) {
  Snapshot s(folder);
  DesignProgress p;
  p.budget = s.budget();
  auto checkpoint = s.db().prepare("SELECT state FROM checkpoint WHERE id = 1");
  if (!checkpoint.step()) return p;
  const json state = json::parse(checkpoint.text(0));
  p.started = true;
  p.phase = state.at("phase").get<std::string>();
  p.nb_iterations = state_integer<int>(state.at("nb_iterations"), "nb_iterations");
  const int finished_iterations = static_cast<int>(state.at("all_elites").size());
  p.iteration = p.phase == "racing" ? state_integer<int>(state.at("iteration"), "iteration") : std::max(1, finished_iterations);
  p.experiments_used = count(s.db(), "SELECT count(*) FROM experiments");
  p.race_budget = state_integer<std::int64_t>(state.at("current_budget"), "current_budget");
  p.race_configurations = state_integer<int>(state.at("nb_configurations"), "nb_configurations");
  if (p.phase == "finished") {  // the figures of the last race run, not of one refused for lack of budget
    p.nb_iterations = p.iteration;
    auto last = s.db().prepare("SELECT race_budget, configurations FROM races ORDER BY iteration DESC LIMIT 1");
    if (last.step()) {
      p.race_budget = last.integer(0);
      p.race_configurations = static_cast<int>(last.integer(1));
    }
  }
  p.configurations_sampled = count(s.db(), "SELECT count(*) FROM configurations");
  if (const json& race = state.at("race"); !race.is_null()) {
    for (const json& alive : race.at("alive")) p.race_alive += alive.get<int>() != 0 ? 1 : 0;
  } else if (p.phase == "finished") {  // the last race as it ended
    p.race_alive = static_cast<int>(count(s.db(),
        "SELECT count(*) FROM race_configurations WHERE eliminated_after IS NULL "
        "AND iteration = (SELECT max(iteration) FROM races)"));
  } else {  // a race about to start: none eliminated yet
    p.race_alive = p.race_configurations;
  }
  p.finish_reason = state.at("finish_reason").get<std::string>();
  const json& elites = state.at("elites");
  const json& race = state.at("race");
  for (const json& elite : elites) p.elites.push_back(configuration_score(s, state_integer<int>(elite.at(0), "elites")));
  if (!elites.empty()) {
    p.best = p.elites.front();
  } else if (!race.is_null() && state_integer<std::size_t>(race.at("next_task"), "race.next_task") > 1) {
    const auto best = state_integer<std::size_t>(race.at("best"), "race.best");
    p.best = configuration_score(s, state_integer<int>(race.at("config_ids").at(best), "race.config_ids"));
  }
  return p;
}

std::vector<RaceRecord> read_race_log(const std::filesystem::path& folder) {
  Snapshot s(folder);
  std::vector<RaceRecord> log;
  auto races = s.db().prepare("SELECT iteration, race_budget FROM races ORDER BY iteration");
  while (races.step()) log.push_back({static_cast<int>(races.integer(0)), races.integer(1), {}, {}, {}});
  for (RaceRecord& r : log) {
    auto instances = s.db().prepare(
        "SELECT position, seed FROM experiments WHERE iteration = ? GROUP BY position ORDER BY min(seq)");
    instances.bind(1, r.iteration);
    while (instances.step()) r.instances.emplace_back(instances.integer(0), instances.integer(1));
    auto members = s.db().prepare(
        "SELECT configuration_id, elite, eliminated_after FROM race_configurations WHERE iteration = ? "
        "ORDER BY elite DESC, configuration_id");
    members.bind(1, r.iteration);
    while (members.step()) {
      RaceMember m;
      m.configuration = configuration_score(s, static_cast<int>(members.integer(0)), r.iteration);
      m.elite = members.integer(1) != 0;
      if (!members.is_null(2)) m.eliminated_after = members.integer(2);
      r.members.push_back(std::move(m));
    }
    auto elites = s.db().prepare("SELECT configuration_id FROM elites WHERE iteration = ? ORDER BY rank");
    elites.bind(1, r.iteration);
    while (elites.step()) r.elites.push_back(static_cast<int>(elites.integer(0)));
  }
  return log;
}

std::vector<ConvergencePoint> read_convergence(const std::filesystem::path& folder) {
  Snapshot s(folder);
  std::vector<ConvergencePoint> points;
  auto best = s.db().prepare(
      "SELECT iteration, configuration_id FROM elites e WHERE rank = (SELECT min(rank) FROM elites WHERE iteration = e.iteration) "
      "ORDER BY iteration");
  while (best.step()) {
    ConvergencePoint p;
    p.iteration = static_cast<int>(best.integer(0));
    p.best_id = static_cast<int>(best.integer(1));
    auto runs = s.db().prepare("SELECT count(*) FROM experiments WHERE iteration <= ?");
    runs.bind(1, p.iteration);
    runs.step();
    p.runs_used = runs.integer(0);
    auto mean = s.db().prepare("SELECT avg(cost) FROM experiments WHERE configuration_id = ? AND iteration <= ?");
    mean.bind(1, p.best_id).bind(2, p.iteration);
    if (mean.step() && !mean.is_null(0)) {
      p.best_score = s.score(mean.real(0));
      points.push_back(p);
    }
  }
  return points;
}

}  // namespace sd::storage
