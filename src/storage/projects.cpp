#include "storage/projects.hpp"

#include "core/private_files.hpp"
#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/folder_removal.hpp"
#include "storage/lease.hpp"
#include "storage/validation.hpp"

namespace sd::storage {

namespace {
// Selects a project with its cluster connection and whether it is the owner's active one;
// ?1 is always the owner.
constexpr std::string_view kSelectProjects =
    "SELECT p.id, p.name, p.path, p.mission, p.budget, c.host, c.user_name, p.created_at, "
    "       a.project_id IS NOT NULL, p.cluster_workdir, p.cluster_binary "
    "FROM projects p "
    "LEFT JOIN cluster_connections c ON c.id = p.cluster_id "
    "LEFT JOIN active_projects a ON a.user_id = p.owner_id AND a.project_id = p.id "
    "WHERE p.owner_id = ?1 ";

Project read_project(const Statement& row, const Workspace& workspace) {
  Project project;
  project.id = row.integer(0);
  project.name = row.text(1);
  project.folder = workspace.resolve(row.text(2));
  if (!row.is_null(3)) project.mission = row.text(3);
  if (!row.is_null(4)) project.budget = row.integer(4);
  if (!row.is_null(5))
    project.cluster = ClusterConnection{row.text(5), row.text(6), row.is_null(9) ? "" : row.text(9),
                                        row.is_null(10) ? "" : row.text(10)};
  project.created_at = row.integer(7);
  project.active = row.integer(8) != 0;
  return project;
}

NotFound no_such_project(std::string_view name) {
  return NotFound("no project named '" + std::string(name) + "'; list yours with: swarmdesign show-projects");
}

std::int64_t cluster_connection_id(Database& db, std::int64_t owner, const ClusterConnection& cluster) {
  db.prepare("INSERT INTO cluster_connections (owner_id, host, user_name) VALUES (?, ?, ?) ON CONFLICT DO NOTHING")
      .bind(1, owner).bind(2, cluster.host).bind(3, cluster.user).run();
  auto query = db.prepare("SELECT id FROM cluster_connections WHERE owner_id = ? AND host = ? AND user_name = ?");
  query.bind(1, owner).bind(2, cluster.host).bind(3, cluster.user);
  query.step();
  return query.integer(0);
}
}  // namespace

Projects::Projects(Workspace& workspace, User owner) : workspace_(workspace), owner_(std::move(owner)) {}

std::optional<Project> Projects::query_one(std::string_view condition, std::string_view value) {
  auto query = workspace_.database().prepare(std::string(kSelectProjects) + std::string(condition));
  query.bind(1, owner_.id).bind(2, value);
  if (!query.step()) return std::nullopt;
  return read_project(query, workspace_);
}

Project Projects::create(std::string_view name, const std::optional<ClusterConnection>& cluster) {
  if (auto problem = project_name_problem(name); !problem.empty()) throw InvalidInput(problem);
  if (cluster) {
    if (auto problem = host_problem(cluster->host); !problem.empty()) throw InvalidInput(problem);
    if (auto problem = cluster_user_problem(cluster->user); !problem.empty()) throw InvalidInput(problem);
    if (auto problem = cluster_path_problem("cluster folder", cluster->workdir); !problem.empty()) throw InvalidInput(problem);
    if (auto problem = cluster_path_problem("cluster binary", cluster->binary); !problem.empty()) throw InvalidInput(problem);
  }
  Database& db = workspace_.database();
  const std::filesystem::path relative = Workspace::projects_folder(owner_) / std::string(name);

  Transaction transaction(db);
  if (query_one("AND p.name = ?2", name))
    throw Conflict("you already have a project named '" + std::string(name) + "'");
  auto insert = db.prepare(
      "INSERT INTO projects (owner_id, name, path, location, cluster_id, created_at, cluster_workdir, cluster_binary) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  insert.bind(1, owner_.id).bind(2, name).bind(3, relative.string()).bind(4, cluster ? "cluster" : "local");
  if (cluster)
    insert.bind(5, cluster_connection_id(db, owner_.id, *cluster));
  else
    insert.bind_null(5);
  insert.bind(6, unix_now());
  for (const auto& [column, value] : {std::pair{7, cluster ? cluster->workdir : ""}, std::pair{8, cluster ? cluster->binary : ""}})
    if (value.empty()) insert.bind_null(column);
    else insert.bind(column, value);
  insert.run();

  // The folder last, just before the commit: a refused project leaves nothing behind. A
  // folder left by an earlier project of the same name is reused.
  const std::filesystem::path folder = workspace_.resolve(relative);
  const bool existed = std::filesystem::exists(folder);
  create_private_folders(folder);
  try {
    transaction.commit();
  } catch (...) {
    if (!existed) std::filesystem::remove(folder);
    throw;
  }
  return get(name);
}

std::vector<Project> Projects::list() {
  std::vector<Project> projects;
  auto query = workspace_.database().prepare(std::string(kSelectProjects) + "ORDER BY p.name");
  query.bind(1, owner_.id);
  while (query.step()) projects.push_back(read_project(query, workspace_));
  return projects;
}

Project Projects::get(std::string_view name) {
  if (auto project = query_one("AND p.name = ?2", name)) return *project;
  throw no_such_project(name);
}

void Projects::remove(std::string_view name) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  const Project project = get(name);
  for (const LeasedTable& table : {kDesignLeases, kExperimentLeases}) {
    Lease(db, table, project.id).sweep_dead();
    auto running = db.prepare("SELECT id FROM " + std::string(table.table) + " WHERE project_id = ? AND state = 'running'");
    running.bind(1, project.id);
    if (running.step())
      throw Conflict("project " + project.name + " has a running " + std::string(table.noun) + " (" +
                     std::to_string(running.integer(0)) + "); stop it before deleting the project");
  }
  // Cascades to its designs, experiments and their results, cluster jobs and the active mark.
  db.prepare("DELETE FROM projects WHERE id = ? AND owner_id = ?").bind(1, project.id).bind(2, owner_.id).run();
  FolderRemoval folder(project.folder);
  transaction.commit();
  folder.commit();
}

Project Projects::select(std::string_view name) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  const Project project = get(name);
  db.prepare("INSERT INTO active_projects (user_id, project_id) VALUES (?, ?) "
             "ON CONFLICT (user_id) DO UPDATE SET project_id = excluded.project_id")
      .bind(1, owner_.id).bind(2, project.id).run();
  transaction.commit();
  return get(name);
}

std::optional<Project> Projects::active() {
  auto query = workspace_.database().prepare(std::string(kSelectProjects) + "AND a.project_id IS NOT NULL");
  query.bind(1, owner_.id);
  if (!query.step()) return std::nullopt;
  return read_project(query, workspace_);
}

Project Projects::require_active() {
  if (auto project = active()) return *project;
  throw NotFound("no active project; choose one with: swarmdesign select-project NAME");
}

Project Projects::set_budget(std::int64_t budget) {
  if (budget < 1) throw InvalidInput("budget must be a positive integer");
  Database& db = workspace_.database();
  Transaction transaction(db);
  const Project project = require_active();
  db.prepare("UPDATE projects SET budget = ? WHERE id = ? AND owner_id = ?")
      .bind(1, budget).bind(2, project.id).bind(3, owner_.id).run();
  transaction.commit();
  return get(project.name);
}

Project Projects::set_mission(const std::string& mission) {
  if (mission.empty()) throw InvalidInput("mission is empty");
  Database& db = workspace_.database();
  Transaction transaction(db);
  const Project project = require_active();
  db.prepare("UPDATE projects SET mission = ? WHERE id = ? AND owner_id = ?")
      .bind(1, mission).bind(2, project.id).bind(3, owner_.id).run();
  transaction.commit();
  return get(project.name);
}

Project Projects::set_cluster_paths(const std::string& workdir, const std::string& binary) {
  if (auto problem = cluster_path_problem("cluster folder", workdir); !problem.empty()) throw InvalidInput(problem);
  if (auto problem = cluster_path_problem("cluster binary", binary); !problem.empty()) throw InvalidInput(problem);
  Database& db = workspace_.database();
  Transaction transaction(db);
  const Project project = require_active();
  if (!project.cluster)
    throw InvalidInput("project " + project.name + " runs on this machine; only a cluster project has cluster settings");
  db.prepare("UPDATE projects SET cluster_workdir = coalesce(nullif(?, ''), cluster_workdir), "
             "cluster_binary = coalesce(nullif(?, ''), cluster_binary) WHERE id = ? AND owner_id = ?")
      .bind(1, workdir).bind(2, binary).bind(3, project.id).bind(4, owner_.id).run();
  transaction.commit();
  return get(project.name);
}

}  // namespace sd::storage
