#include "storage/experiments.hpp"

#include "core/private_files.hpp"
#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/lease.hpp"

namespace sd::storage {

namespace {

constexpr std::string_view kSelectExperiments =
    "SELECT id, name, protocol, state, owner, heartbeat_at, path, created_at, updated_at, finished_at "
    "FROM experiments WHERE project_id = ? ";

constexpr std::string_view kSelectDesigns =
    "SELECT d.id, d.mission, d.condition, d.replicate, d.method, d.architectures, d.flavours, d.budget, d.seed, d.stage, "
    "       d.configuration, d.design_score, d.runs_used, d.wall_seconds, d.reused_from, e.path, e.name "
    "FROM experiment_designs d JOIN experiments e ON e.id = d.experiment_id ";

DesignStage stage_from(const std::string& text) {
  if (text == "designing") return DesignStage::designing;
  if (text == "assessing") return DesignStage::assessing;
  if (text == "done") return DesignStage::done;
  return DesignStage::pending;
}

Experiment read_experiment(const Statement& row, const Workspace& workspace) {
  Experiment e;
  e.id = row.integer(0);
  e.name = row.text(1);
  e.protocol = row.text(2);
  e.state = design_state_from(row.text(3));
  e.owner = row.text(4);
  e.heartbeat_at = row.integer(5);
  e.folder = workspace.resolve(row.text(6));
  e.created_at = row.integer(7);
  e.updated_at = row.integer(8);
  if (!row.is_null(9)) e.finished_at = row.integer(9);
  // Reading must not need the write lock: a dead "running" experiment reads as interrupted.
  if (e.state == DesignState::running && !owner_alive(e.owner, e.heartbeat_at, unix_now(), 0))
    e.state = DesignState::interrupted;
  return e;
}

/// A row of kSelectDesigns.
ExperimentDesign read_design(const Statement& row, const Workspace& workspace) {
  ExperimentDesign d;
  d.id = row.integer(0);
  d.plan = {row.text(1), row.text(2), static_cast<int>(row.integer(3)), row.text(4), row.text(5),
            row.text(6), row.integer(7), static_cast<std::uint64_t>(row.integer(8))};
  d.stage = stage_from(row.text(9));
  if (!row.is_null(10)) d.configuration = row.text(10);
  if (!row.is_null(11)) d.design_score = row.real(11);
  if (!row.is_null(12)) d.runs_used = row.integer(12);
  d.wall_seconds = row.real(13);
  if (!row.is_null(14)) d.reused_from = row.integer(14);
  d.folder = workspace.resolve(row.text(15)) / std::to_string(d.id);
  return d;
}

}  // namespace

std::string to_string(DesignStage stage) {
  switch (stage) {
    case DesignStage::pending: return "pending";
    case DesignStage::designing: return "designing";
    case DesignStage::assessing: return "assessing";
    case DesignStage::done: return "done";
  }
  return "pending";
}

Experiments::Experiments(Workspace& workspace, Project project) : workspace_(workspace), project_(std::move(project)) {}

Lease Experiments::lease() { return Lease(workspace_.database(), kExperimentLeases, project_.id); }

std::pair<Experiment, bool> Experiments::start(const std::string& name, const std::string& protocol,
                                               const std::vector<PlannedDesign>& designs, const std::string& owner) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  lease().sweep_dead();
  const std::int64_t now = unix_now();

  if (const auto existing = find(name)) {
    if (existing->protocol != protocol)
      throw Conflict("project " + project_.name + " already has an experiment '" + name +
                     "' with another protocol (other missions, designs, budgets or seeds); give this one "
                     "another name with --name, or repeat the first command to resume it");
    if (existing->state == DesignState::running)
      throw Conflict("experiment '" + name + "' of project " + project_.name + " is still running; watch it with: swarmdesign status");
    if (existing->state == DesignState::finished) {
      transaction.commit();
      return {*existing, true};
    }
    db.prepare("UPDATE experiments SET state = 'running', finished_at = NULL WHERE id = ?").bind(1, existing->id).run();
    lease().hand_over(existing->id, owner);
    transaction.commit();
    return {get_by_id(existing->id), true};
  }

  const auto project_folder = std::filesystem::relative(project_.folder, workspace_.home());
  db.prepare("INSERT INTO experiments (project_id, name, protocol, owner, heartbeat_at, path, created_at, updated_at) "
             "VALUES (?, ?, ?, ?, ?, '', ?, ?)")
      .bind(1, project_.id).bind(2, name).bind(3, protocol).bind(4, owner).bind(5, now).bind(6, now).bind(7, now).run();
  const std::int64_t id = db.last_insert_id();
  const auto folder = project_folder / "experiments" / std::to_string(id);
  db.prepare("UPDATE experiments SET path = ? WHERE id = ?").bind(1, folder.string()).bind(2, id).run();
  auto insert = db.prepare(
      "INSERT INTO experiment_designs (experiment_id, mission, condition, replicate, method, architectures, flavours, "
      "budget, seed) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (const PlannedDesign& d : designs) {
    insert.bind(1, id).bind(2, d.mission).bind(3, d.condition).bind(4, d.replicate).bind(5, d.method)
        .bind(6, d.architectures).bind(7, d.flavours).bind(8, d.budget).bind(9, static_cast<std::int64_t>(d.seed)).run();
  }
  create_private_folders(workspace_.resolve(folder));
  transaction.commit();
  return {get_by_id(id), false};
}

bool Experiments::heartbeat(std::int64_t experiment_id, const std::string& owner) {
  return lease().renew(experiment_id, owner);
}

void Experiments::finish(std::int64_t experiment_id) {
  const std::int64_t now = unix_now();
  workspace_.database()
      .prepare("UPDATE experiments SET state = 'finished', updated_at = ?, finished_at = ? WHERE id = ? AND project_id = ?")
      .bind(1, now).bind(2, now).bind(3, experiment_id).bind(4, project_.id).run();
}

void Experiments::release(std::int64_t experiment_id, const std::string& owner) { lease().release(experiment_id, owner); }

std::optional<Experiment> Experiments::find(const std::string& name) {
  auto query = workspace_.database().prepare(std::string(kSelectExperiments) + "AND name = ?");
  query.bind(1, project_.id).bind(2, name);
  if (!query.step()) return std::nullopt;
  return read_experiment(query, workspace_);
}

Experiment Experiments::get(const std::string& name) {
  if (auto e = find(name)) return *e;
  std::string has;
  for (const auto& e : list()) has += (has.empty() ? "" : ", ") + e.name;
  throw NotFound("project " + project_.name + " has no experiment '" + name + "'" +
                 (has.empty() ? " (it has none yet; run one with: swarmdesign experiment validation)" : " (it has " + has + ")"));
}

Experiment Experiments::get_by_id(std::int64_t id) {
  auto query = workspace_.database().prepare(std::string(kSelectExperiments) + "AND id = ?");
  query.bind(1, project_.id).bind(2, id);
  if (!query.step()) throw NotFound("project " + project_.name + " has no experiment " + std::to_string(id));
  return read_experiment(query, workspace_);
}

std::vector<Experiment> Experiments::list() {
  std::vector<Experiment> all;
  auto query = workspace_.database().prepare(std::string(kSelectExperiments) + "ORDER BY id");
  query.bind(1, project_.id);
  while (query.step()) all.push_back(read_experiment(query, workspace_));
  return all;
}

std::vector<ExperimentDesign> Experiments::designs(std::int64_t experiment_id) {
  get_by_id(experiment_id);  // NotFound for another project's
  std::vector<ExperimentDesign> all;
  auto query = workspace_.database().prepare(std::string(kSelectDesigns) + "WHERE d.experiment_id = ? ORDER BY d.id");
  query.bind(1, experiment_id);
  while (query.step()) all.push_back(read_design(query, workspace_));
  return all;
}

ExperimentDesign Experiments::design(std::int64_t design_id) {
  auto query = workspace_.database().prepare(std::string(kSelectDesigns) + "WHERE d.id = ? AND e.project_id = ?");
  query.bind(1, design_id).bind(2, project_.id);
  if (!query.step()) throw NotFound("project " + project_.name + " has no experiment design " + std::to_string(design_id));
  return read_design(query, workspace_);
}

std::optional<std::pair<ExperimentDesign, std::string>> Experiments::finished_twin(const ExperimentDesign& d) {
  auto query = workspace_.database().prepare(
      std::string(kSelectDesigns) +
      "WHERE e.project_id = ? AND d.experiment_id <> (SELECT experiment_id FROM experiment_designs WHERE id = ?) "
      "AND d.mission = ? AND d.method = ? AND d.architectures = ? AND d.flavours = ? AND d.budget = ? AND d.seed = ? "
      "AND d.stage IN ('assessing', 'done') AND d.reused_from IS NULL ORDER BY d.id LIMIT 1");
  query.bind(1, project_.id).bind(2, d.id).bind(3, d.plan.mission).bind(4, d.plan.method).bind(5, d.plan.architectures)
      .bind(6, d.plan.flavours).bind(7, d.plan.budget).bind(8, static_cast<std::int64_t>(d.plan.seed));
  if (!query.step()) return std::nullopt;
  return std::pair{read_design(query, workspace_), query.text(16)};
}

void Experiments::reuse(std::int64_t design_id, const ExperimentDesign& twin) {
  require_design(design_id);
  Database& db = workspace_.database();
  Transaction transaction(db);
  db.prepare("UPDATE experiment_designs SET stage = 'assessing', configuration = ?, design_score = ?, runs_used = ?, "
             "wall_seconds = ?, reused_from = ? WHERE id = ?")
      .bind(1, twin.configuration.value()).bind(2, twin.design_score.value_or(0.0)).bind(3, twin.runs_used.value_or(0))
      .bind(4, twin.wall_seconds).bind(5, twin.id).bind(6, design_id).run();
  transaction.commit();
}

void Experiments::require_design(std::int64_t design_id) {
  auto query = workspace_.database().prepare(
      "SELECT 1 FROM experiment_designs d JOIN experiments e ON e.id = d.experiment_id WHERE d.id = ? AND e.project_id = ?");
  query.bind(1, design_id).bind(2, project_.id);
  if (!query.step()) throw NotFound("project " + project_.name + " has no experiment design " + std::to_string(design_id));
}

void Experiments::set_stage(std::int64_t design_id, DesignStage stage) {
  require_design(design_id);
  workspace_.database().prepare("UPDATE experiment_designs SET stage = ? WHERE id = ?").bind(1, to_string(stage)).bind(2, design_id).run();
}

void Experiments::design_finished(std::int64_t design_id, const std::string& configuration, double design_score,
                                  std::int64_t runs_used) {
  require_design(design_id);
  workspace_.database()
      .prepare("UPDATE experiment_designs SET stage = 'assessing', configuration = ?, design_score = ?, runs_used = ? "
               "WHERE id = ?")
      .bind(1, configuration).bind(2, design_score).bind(3, runs_used).bind(4, design_id).run();
}

void Experiments::add_wall_seconds(std::int64_t design_id, double seconds) {
  require_design(design_id);
  workspace_.database()
      .prepare("UPDATE experiment_designs SET wall_seconds = wall_seconds + ? WHERE id = ?")
      .bind(1, seconds).bind(2, design_id).run();
}

void Experiments::record_assessment(std::int64_t design_id, const std::vector<std::uint64_t>& seeds,
                                    const std::vector<double>& scores, const std::vector<RealityScore>& reality) {
  require_design(design_id);
  Database& db = workspace_.database();
  Transaction transaction(db);
  db.prepare("DELETE FROM experiment_assessments WHERE design_id = ?").bind(1, design_id).run();
  db.prepare("DELETE FROM experiment_reality_assessments WHERE design_id = ?").bind(1, design_id).run();
  auto insert = db.prepare("INSERT INTO experiment_assessments (design_id, seed, score) VALUES (?, ?, ?)");
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    insert.bind(1, design_id).bind(2, static_cast<std::int64_t>(seeds[i])).bind(3, scores.at(i)).run();
  }
  auto insert_reality =
      db.prepare("INSERT INTO experiment_reality_assessments (design_id, sample, seed, score) VALUES (?, ?, ?, ?)");
  for (const RealityScore& r : reality)
    insert_reality.bind(1, design_id).bind(2, static_cast<std::int64_t>(r.sample)).bind(3, static_cast<std::int64_t>(r.seed))
        .bind(4, r.score).run();
  db.prepare("UPDATE experiment_designs SET stage = 'done' WHERE id = ?").bind(1, design_id).run();
  transaction.commit();
}

std::vector<std::pair<std::uint64_t, double>> Experiments::assessments(std::int64_t design_id) {
  require_design(design_id);
  std::vector<std::pair<std::uint64_t, double>> scores;
  auto query = workspace_.database().prepare(
      "SELECT seed, score FROM experiment_assessments WHERE design_id = ? ORDER BY seed");
  query.bind(1, design_id);
  while (query.step()) scores.emplace_back(static_cast<std::uint64_t>(query.integer(0)), query.real(1));
  return scores;
}

std::vector<RealityScore> Experiments::reality_assessments(std::int64_t design_id) {
  require_design(design_id);
  std::vector<RealityScore> scores;
  auto query = workspace_.database().prepare(
      "SELECT sample, seed, score FROM experiment_reality_assessments WHERE design_id = ? ORDER BY sample, seed");
  query.bind(1, design_id);
  while (query.step())
    scores.push_back({static_cast<std::uint64_t>(query.integer(0)), static_cast<std::uint64_t>(query.integer(1)), query.real(2)});
  return scores;
}

}  // namespace sd::storage
