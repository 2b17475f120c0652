// A project's running design stopped (`stop-design`, through its backend: app/design_backends.hpp),
// and what a cluster project's cluster lacks (`cluster-check`, app/cluster_designs.hpp).
#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

#include "app/accounts.hpp"
#include "app/cluster_designs.hpp"
#include "app/design_backends.hpp"
#include "cli/command_registry.hpp"

namespace sd::cli::cluster_commands {
namespace {

struct Options {
  std::string project;
  bool json = false;
};

std::optional<std::string> named(const Options& o) {
  return o.project.empty() ? std::nullopt : std::optional<std::string>(o.project);
}

void stop(const Options& o) {
  app::Home home;
  const app::StoppedDesign stopped = app::stop_design(home, app::signed_in_user(home), named(o));
  if (o.json) {
    std::cout << nlohmann::json{{"design", stopped.design.id}, {"state", storage::to_string(stopped.design.state)},
                                {"how", stopped.how}}
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << "Design " << stopped.design.id << " stopped (" << stopped.how << "); it is "
            << storage::to_string(stopped.design.state) << ".\nContinue it with: swarmdesign run-design\n";
}

int check(const Options& o) {
  app::Home home;
  const app::ClusterCheckReport report = app::check_project_cluster(home, app::signed_in_user(home), named(o));
  if (o.json) {
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& c : report.checks) checks.push_back({{"what", c.what}, {"ok", c.ok}, {"detail", c.detail}});
    std::cout << nlohmann::json{{"project", report.project.name}, {"where", report.where}, {"ok", report.ok()},
                                {"checks", checks}}
                     .dump(2)
              << "\n";
  } else {
    std::cout << "Cluster of project " << report.project.name << " (" << report.where << "):\n";
    for (const auto& c : report.checks)
      std::cout << "  " << (c.ok ? "ok      " : "MISSING ") << c.what << ": " << c.detail << "\n";
    std::cout << (report.ok() ? "Ready: run-design submits this project's designs as Slurm jobs.\n"
                              : "Not ready: fix what is missing above, then run cluster-check again.\n");
  }
  return report.ok() ? 0 : 1;
}

CommandRegistrar registrar{42, [](CLI::App& app, Context&) {
  auto o = std::make_shared<Options>();
  auto* stop_cmd = app.add_subcommand("stop-design", "Stop the active project's running design (it can be resumed)");
  stop_cmd->add_option("--project", o->project, "Another of your projects than the active one");
  stop_cmd->add_flag("--json", o->json, "Print one JSON document");
  stop_cmd->footer("A cluster project's design is cancelled with scancel; a local one's process is sent SIGTERM.\n"
                   "Either way it becomes interrupted, and run-design resumes it from its last checkpoint.\n\n"
                   "Example:\n  swarmdesign stop-design");
  stop_cmd->callback([o] { stop(*o); });

  auto* check_cmd = app.add_subcommand("cluster-check", "Tell what a cluster project's cluster lacks to run designs");
  check_cmd->add_option("--project", o->project, "Another of your projects than the active one");
  check_cmd->add_flag("--json", o->json, "Print one JSON document");
  check_cmd->footer("Checks, on the login node (over ssh unless it is this machine): that it can be reached, that\n"
                    "sbatch, squeue and scancel are on the path, that its swarmdesign is this version (same\n"
                    "results version: same scores), that the job folder can be written, and whether mpirun is\n"
                    "there. Exit status 1 when something is missing.\n\n"
                    "Example:\n  swarmdesign cluster-check");
  check_cmd->callback([o] {
    if (const int status = check(*o); status != 0) throw CLI::RuntimeError(status);
  });
}};

}  // namespace
}  // namespace sd::cli::cluster_commands
