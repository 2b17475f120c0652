#include "storage/designs.hpp"

#include <vector>

#include "core/private_files.hpp"
#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/folder_removal.hpp"
#include "storage/lease.hpp"

namespace sd::storage {

namespace {
constexpr std::string_view kSelectDesigns =
    "SELECT id, architectures, flavours, mission, budget, seed, state, pid, path, best_config, best_score, "
    "       created_at, updated_at, finished_at, coalesce(owner, ''), coalesce(heartbeat_at, 0), method "
    "FROM designs WHERE project_id = ? ";

Design read_design(const Statement& row, const Workspace& workspace) {
  Design design;
  design.id = row.integer(0);
  design.architectures = row.text(1);
  design.flavours = row.text(2);
  design.mission = row.text(3);
  design.budget = row.integer(4);
  design.seed = static_cast<std::uint64_t>(row.integer(5));  // stored as its 64-bit pattern
  design.state = design_state_from(row.text(6));
  design.pid = static_cast<int>(row.integer(7));
  design.folder = workspace.resolve(row.text(8));
  if (!row.is_null(9)) design.best_config = row.text(9);
  if (!row.is_null(10)) design.best_score = row.real(10);
  design.created_at = row.integer(11);
  design.updated_at = row.integer(12);
  if (!row.is_null(13)) design.finished_at = row.integer(13);
  design.owner = row.text(14);
  design.heartbeat_at = row.integer(15);
  design.method = row.text(16);
  return design;
}
}  // namespace

DesignState design_state_from(const std::string& text) {
  if (text == "finished") return DesignState::finished;
  if (text == "failed") return DesignState::failed;
  if (text == "interrupted") return DesignState::interrupted;
  return DesignState::running;
}

std::string to_string(DesignState state) {
  switch (state) {
    case DesignState::running: return "running";
    case DesignState::finished: return "finished";
    case DesignState::failed: return "failed";
    case DesignState::interrupted: return "interrupted";
  }
  return "running";
}

namespace {

/// Reading must not need the write lock: a dead "running" design is reported interrupted, the
/// same by latest() and list() (a list and a status box never disagree).
Design as_reported(Design design) {
  if (design.state == DesignState::running && !owner_alive(design.owner, design.heartbeat_at, unix_now(), design.pid))
    design.state = DesignState::interrupted;
  return design;
}

}  // namespace

Designs::Designs(Workspace& workspace, Project project) : workspace_(workspace), project_(std::move(project)) {}

Lease Designs::lease() { return Lease(workspace_.database(), kDesignLeases, project_.id); }

Design Designs::start(const DesignRequest& request) {
  if (!project_.mission) throw NotFound("project " + project_.name + " has no mission; choose one with: swarmdesign set-mission");
  if (!project_.budget) throw NotFound("project " + project_.name + " has no budget; set one with: swarmdesign set-budget N");
  if (request.architectures.empty() || request.flavours.empty())
    throw InvalidInput("a design needs at least one architecture and one flavour");

  Database& db = workspace_.database();
  Transaction transaction(db);
  lease().sweep_dead();
  auto running = db.prepare("SELECT id FROM designs WHERE project_id = ? AND state = 'running'");
  running.bind(1, project_.id);
  if (running.step())
    throw Conflict("design " + std::to_string(running.integer(0)) + " of project " + project_.name +
                   " is still running; watch it with: swarmdesign status");

  const std::int64_t now = unix_now();
  const auto project_folder = std::filesystem::relative(project_.folder, workspace_.home());
  db.prepare("INSERT INTO designs (project_id, architectures, flavours, mission, budget, seed, pid, owner, heartbeat_at, "
             "path, created_at, updated_at, method) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, '', ?, ?, ?)")
      .bind(1, project_.id).bind(2, request.architectures).bind(3, request.flavours).bind(4, *project_.mission)
      .bind(5, *project_.budget).bind(6, static_cast<std::int64_t>(request.seed)).bind(7, owner_pid(request.owner))
      .bind(8, request.owner).bind(9, now).bind(10, now).bind(11, now).bind(12, request.method).run();
  const std::int64_t id = db.last_insert_id();
  const auto folder = project_folder / "designs" / std::to_string(id);
  db.prepare("UPDATE designs SET path = ? WHERE id = ?").bind(1, folder.string()).bind(2, id).run();
  create_private_folders(workspace_.resolve(folder));
  transaction.commit();
  return get(id);
}

void Designs::set_state(std::int64_t design_id, DesignState state, std::string_view from_states) {
  Database& db = workspace_.database();
  db.prepare("UPDATE designs SET state = ?, updated_at = ? WHERE id = ? AND project_id = ? AND state IN " +
             std::string(from_states))
      .bind(1, to_string(state)).bind(2, unix_now()).bind(3, design_id).bind(4, project_.id).run();
  if (db.changes() == 0) throw Conflict("design " + std::to_string(design_id) + " cannot become " + to_string(state) + " now");
}

Design Designs::resume(std::int64_t design_id, const std::string& owner) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  lease().sweep_dead();
  get(design_id);  // NotFound for another project's design
  auto running = db.prepare("SELECT id FROM designs WHERE project_id = ? AND state = 'running'");
  running.bind(1, project_.id);
  if (running.step())
    throw Conflict("design " + std::to_string(running.integer(0)) + " of project " + project_.name + " is still running");
  set_state(design_id, DesignState::running, "('interrupted', 'failed')");
  lease().hand_over(design_id, owner);
  transaction.commit();
  return get(design_id);
}

void Designs::set_owner(std::int64_t design_id, const std::string& owner) { lease().hand_over(design_id, owner); }

bool Designs::heartbeat(std::int64_t design_id, const std::string& owner) { return lease().renew(design_id, owner); }

void Designs::release(std::int64_t design_id, const std::string& owner) { lease().release(design_id, owner); }

void Designs::finish(std::int64_t design_id, const std::string& best_config, double best_score) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  set_state(design_id, DesignState::finished, "('running')");
  db.prepare("UPDATE designs SET best_config = ?, best_score = ?, finished_at = updated_at WHERE id = ?")
      .bind(1, best_config).bind(2, best_score).bind(3, design_id).run();
  transaction.commit();
}

void Designs::abandon(std::int64_t design_id) { fail(design_id, "('interrupted')"); }

void Designs::mark_failed(std::int64_t design_id) { fail(design_id, "('running', 'interrupted')"); }

void Designs::fail(std::int64_t design_id, std::string_view from_states) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  lease().sweep_dead();  // a dead design's row may still say "running"
  set_state(design_id, DesignState::failed, from_states);
  db.prepare("UPDATE designs SET finished_at = updated_at WHERE id = ?").bind(1, design_id).run();
  transaction.commit();
}

void Designs::remove(std::int64_t design_id) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  lease().sweep_dead();
  const Design design = get(design_id);
  if (design.state == DesignState::running)
    throw Conflict("design " + std::to_string(design_id) + " of project " + project_.name +
                   " is running; stop it first (swarmdesign stop-design)");
  db.prepare("DELETE FROM designs WHERE id = ? AND project_id = ?").bind(1, design_id).bind(2, project_.id).run();
  FolderRemoval folder(design.folder);
  transaction.commit();
  folder.commit();
}

Design Designs::get(std::int64_t design_id) {
  auto query = workspace_.database().prepare(std::string(kSelectDesigns) + "AND id = ?");
  query.bind(1, project_.id).bind(2, design_id);
  if (!query.step()) throw NotFound("project " + project_.name + " has no design " + std::to_string(design_id));
  return read_design(query, workspace_);
}

std::optional<Design> Designs::latest() {
  auto query = workspace_.database().prepare(std::string(kSelectDesigns) + "ORDER BY id DESC LIMIT 1");
  query.bind(1, project_.id);
  if (!query.step()) return std::nullopt;
  return as_reported(read_design(query, workspace_));
}

std::vector<Design> Designs::list() {
  std::vector<Design> designs;
  auto query = workspace_.database().prepare(std::string(kSelectDesigns) + "ORDER BY id");
  query.bind(1, project_.id);
  while (query.step()) designs.push_back(as_reported(read_design(query, workspace_)));
  return designs;
}

}  // namespace sd::storage
