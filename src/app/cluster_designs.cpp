#include "app/cluster_designs.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <thread>

#include "app/documents/design.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/projects.hpp"
#include "app/version.hpp"
#include "cluster/slurm.hpp"
#include "cluster/transfer.hpp"
#include "missions/catalogue.hpp"
#include "storage/clock.hpp"
#include "storage/design_store.hpp"
#include "storage/lease.hpp"

namespace sd::app {

namespace {

using nlohmann::json;

std::string slurm_owner(const std::string& job_id, const storage::Project& project) {
  return storage::owner_text(storage::SlurmJob{job_id, project.cluster->host});
}

/// The job: the design started in design/ or, when design/ already holds one (a job submitted
/// again), resumed from its last checkpoint. Several tasks run it under mpirun (rank 0 races);
/// each task evaluates on the CPUs Slurm gave it.
std::string job_body(const std::string& folder, const storage::Design& d, const std::string& binary,
                     const ClusterJobRequest& request) {
  const std::string q = cluster::shell_quote(folder);
  return "set -u\n"
         "cd " + q + " || exit 1\n"
         "if [ -f design/design.db ]; then\n"
         // Submitted again right after its predecessor was cut (TIMEOUT, scancel), the job may
         // start while that one still saves its last checkpoint within Slurm's KillWait: wait
         // for it to let go of the design rather than fail on its lock.
         "  command -v flock >/dev/null 2>&1 && [ -f design/design.lock ] && flock -w 300 design/design.lock true\n"
         "  set -- design --resume \"$PWD/design\"\n"
         "else\n"
         "  set -- design --mission \"$PWD/mission.json\" --budget " + std::to_string(d.budget) +
         " --seed " + std::to_string(d.seed) + space_flags(d.architectures, d.flavours) + method_flag(d.method) +
         " --out \"$PWD/design\"\n"
         "fi\n" +
         design_command_line(binary, request);
}

/// Writes the job's files (the folder made absolute there) and submits it: the job id.
std::string submit_job(const cluster::Shell& shell, const storage::Project& project, const storage::Design& d,
                       const std::string& folder, const std::string& mission_document, const ClusterJobRequest& r) {
  const auto settings = job_settings(r, "sd-" + project.name + "-" + std::to_string(d.id), folder, "slurm-%j.out");
  if (!mission_document.empty()) cluster::write_file(shell, folder + "/mission.json", mission_document);
  const std::string body = job_body(folder, d, project.cluster->binary_or_default(), r);
  cluster::write_file(shell, folder + "/job.sh", cluster::sbatch_script(settings, body), true);
  return cluster::submit(shell, folder + "/job.sh");
}

std::string planned_job_folder(const storage::Project& project, const storage::User& user, std::int64_t design_id) {
  return project.cluster->workdir_or_default() + "/" + user.name + "/" + project.name + "/design-" +
         std::to_string(design_id);
}

/// The design's job folder on the cluster, created, as an absolute path there.
std::string make_job_folder(const cluster::Shell& shell, const storage::Project& project, const storage::User& user,
                            std::int64_t design_id) {
  return make_cluster_folder(shell, planned_job_folder(project, user, design_id));
}

std::string last_line(const std::string& text) {
  auto end = text.find_last_not_of(" \n\r\t");
  if (end == std::string::npos) return "";
  const auto start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

/// How much of a job's log is read for its last line: a long design's log holds its whole progress.
constexpr std::size_t kLogEndBytes = std::size_t{64} << 10;

/// One line on a job that ended before its design finished.
std::string ended_note(const cluster::Shell& shell, const storage::ClusterJob& job, const cluster::JobStatus& status) {
  const std::string again = "; run-design submits it again and it resumes from its last checkpoint";
  const std::string log = job.folder + "/slurm-" + job.job_id + ".out";
  std::string said;
  try {
    if (const auto text = cluster::read_file(shell, log, kLogEndBytes)) said = last_line(*text);
  } catch (const cluster::ClusterError&) {
  }
  const std::string j = "Slurm job " + job.job_id;
  switch (status.state) {
    case cluster::JobState::timeout: return j + " reached its time limit before the design finished" + again;
    case cluster::JobState::cancelled: return j + " was cancelled" + (status.reason.empty() ? "" : " (" + status.reason + ")") + again;
    case cluster::JobState::unknown: return "Slurm no longer knows job " + job.job_id + " and it left no result" + again;
    default: break;
  }
  std::string note = j + " ended (" + status.slurm_state + ", exit code " + std::to_string(status.exit_code) +
                     ") before the design finished";
  if (!said.empty()) note += ": " + said;
  return note + " (log: " + log + ")" + again;
}

std::optional<storage::DesignProgress> progress_there(const cluster::Shell& shell, const storage::Project& project,
                                                      const std::string& folder) {
  const std::string design = folder + "/design";
  try {
    if (shell.local()) {
      const auto path = cluster::local_path(design);
      if (!std::filesystem::exists(storage::DesignStore::file_in(path))) return std::nullopt;
      return storage::read_design_progress(path);
    }
    const auto out = shell.run_checked(cluster::shell_path(project.cluster->binary_or_default()) + " design-status " +
                                       cluster::shell_quote(design) + " --json");
    if (out.exit_code != 0) return std::nullopt;  // no checkpoint yet
    return stored_progress_from_document(json::parse(out.out));
  } catch (const std::exception&) {
    return std::nullopt;  // a checkpoint being written; the next status reads it
  }
}


}  // namespace

bool ClusterCheckReport::ok() const {
  for (const auto& c : checks)
    if (!c.ok) return false;
  return true;
}


ClusterSubmission submit_cluster_design(Home& home, const storage::User& user, const ProjectDesignRequest& request,
                                        const ClusterJobRequest& given) {
  check_request(given);
  storage::Workspace& workspace = home.workspace();
  const storage::Project project = project_or_active(home, user, request.project);
  if (!project.cluster)
    throw InvalidRequest("project " + project.name + " runs on this machine; --nodes, --ntasks, --cpus-per-task, --time, "
                         "--partition and --account are for a cluster project");
  storage::Designs designs(workspace, project);
  storage::ClusterJobs jobs(workspace, project);
  const cluster::Shell shell = cluster_shell(project);

  auto latest = designs.latest();
  if (latest && latest->state == storage::DesignState::running) {
    refresh_cluster_design(home, project, *latest);
    if (latest->state == storage::DesignState::running) {
      const auto job = jobs.find(latest->id);
      throw Conflict("design " + std::to_string(latest->id) + " of " + project.name + " is still running" +
                     (job && !job->job_id.empty() ? " as Slurm job " + job->job_id : "") +
                     "; watch it with: swarmdesign status (stop it with: swarmdesign stop-design)");
    }
  }

  ClusterSubmission out{project, {}, {}, false, shell.describe()};
  // Whatever stops a submission, the design is left interrupted, with the cluster's one-line
  // reason as its note: run-design submits it again.
  const auto submitting = [&](const std::function<void()>& submit) {
    try {
      submit();
    } catch (const cluster::ClusterError& e) {
      designs.release(out.design.id, out.design.owner);
      jobs.observed(out.design.id, "", e.what());
      throw;
    } catch (...) {
      designs.release(out.design.id, out.design.owner);
      throw;
    }
  };
  const auto previous = latest ? jobs.find(latest->id) : std::nullopt;
  if (latest && latest->state == storage::DesignState::interrupted && previous && !request.fresh) {
    // Submitted again: the job resumes the design from the checkpoint in its folder.
    const ClusterJobRequest settings = merged(previous->settings, given);
    check_request(settings);
    out.design = designs.resume(latest->id, storage::owner_text(storage::slurm_submitting()));
    out.resubmitted = !previous->job_id.empty();
    submitting([&] {
      // A first submission that never reached Slurm (an unreachable host, say) is made anew.
      const bool never_submitted = previous->job_id.empty();
      const std::string folder = never_submitted ? make_job_folder(shell, project, user, out.design.id) : previous->folder;
      const std::string mission = never_submitted ? load_mission(out.design.mission).document : "";
      const std::string job_id = submit_job(shell, project, out.design, folder, mission, settings);
      jobs.submitted(out.design.id, job_id, folder, settings_text(settings));
      designs.set_owner(out.design.id, slurm_owner(job_id, project));
    });
  } else {
    const std::uint64_t seed = request.seed ? *request.seed : random_seed();
    if (!project.mission) throw NotFound("project " + project.name + " has no mission; choose one with: swarmdesign set-mission");
    if (!project.budget) throw NotFound("project " + project.name + " has no budget; set one with: swarmdesign set-budget N");
    const PreparedDesign checked = check_new_design(
        {*project.mission, *project.budget, request.space, seed, FileScope::local(), {}, {}, {}, request.method});
    if (latest && latest->state == storage::DesignState::interrupted && request.fresh) designs.abandon(latest->id);
    out.design = designs.start({checked.choice.architectures_text(), checked.choice.flavours_text(), seed,
                                storage::owner_text(storage::slurm_submitting()), std::string(request.method->name)});
    submitting([&] {
      // Recorded before the cluster is asked anything, so that a failure has a row to note it
      // in and run-design can submit this design again.
      jobs.submitted(out.design.id, "", planned_job_folder(project, user, out.design.id), settings_text(given));
      const std::string folder = make_job_folder(shell, project, user, out.design.id);
      const std::string job_id = submit_job(shell, project, out.design, folder, checked.mission.document, given);
      jobs.submitted(out.design.id, job_id, folder, settings_text(given));
      designs.set_owner(out.design.id, slurm_owner(job_id, project));
    });
  }
  out.design = storage::Designs(home.workspace(), project).get(out.design.id);
  out.job = *jobs.find(out.design.id);
  return out;
}

std::optional<storage::DesignProgress> refresh_cluster_design(Home& home, const storage::Project& project,
                                                              storage::Design& design) {
  if (!project.cluster || design.state != storage::DesignState::running) return std::nullopt;
  storage::ClusterJobs jobs(home.workspace(), project);
  const auto job = jobs.find(design.id);
  if (!job || job->job_id.empty()) {
    // Its submitting process stopped before Slurm took the job (or is still at it).
    if (job && storage::unix_now() - job->submitted_at < kSubmissionGraceSeconds) return std::nullopt;
    storage::Designs(home.workspace(), project).release(design.id, design.owner);
    if (job) jobs.observed(design.id, "", "its submission did not complete; run-design submits it again");
    design = storage::Designs(home.workspace(), project).get(design.id);
    return std::nullopt;
  }
  try {
    const cluster::Shell shell = cluster_shell(project);
    const cluster::JobStatus status = cluster::job_status(shell, job->job_id);
    if (!cluster::finished(status.state) && status.state != cluster::JobState::unknown) {
      jobs.observed(design.id, status.slurm_state, "");
      return progress_there(shell, project, job->folder);
    }
    // The job has ended: its design folder comes home, finished or not.
    storage::Designs designs(home.workspace(), project);
    if (cluster::exists(shell, job->folder + "/design/design.db"))
      cluster::fetch_folder(shell, job->folder + "/design", design.folder);
    std::optional<storage::DesignProgress> final_progress;
    if (std::filesystem::exists(storage::DesignStore::file_in(design.folder)))
      final_progress = storage::read_design_progress(design.folder);
    if (final_progress && final_progress->phase == "finished" && final_progress->best) {
      designs.finish(design.id, final_progress->best->command_line, final_progress->best->mean_score);
      jobs.observed(design.id, status.slurm_state.empty() ? "COMPLETED" : status.slurm_state, "");
    } else {
      designs.release(design.id, design.owner);
      jobs.observed(design.id, status.slurm_state, ended_note(shell, *job, status));
    }
    design = storage::Designs(home.workspace(), project).get(design.id);
  } catch (const cluster::ClusterError& e) {
    jobs.observed(design.id, "", e.what());
  }
  return std::nullopt;
}

StartedDesign SlurmJobs::start(Home& home, const storage::User& user, const DesignLaunch& launch) {
  if (launch.detach) throw InvalidRequest("--detach is for a local project: a cluster project's design runs as a Slurm job anyway");
  // The job script runs `design` on the cluster from the project's settings, which do not
  // carry a specification file there yet.
  if (!launch.design.pseudo_reality.empty())
    throw InvalidRequest("--pseudo-reality: robust designs run in a local project or on a server; not yet as Slurm jobs");
  ClusterSubmission s = submit_cluster_design(home, user, launch.design, launch.slurm);
  StartedDesign out{s.project, s.design, s.resubmitted, std::nullopt, {}, std::nullopt, false, 0, s.job, s.where};
  return out;
}

StoppedDesign SlurmJobs::stop(Home& home, const storage::Project& project, const storage::Design& design) {
  storage::ClusterJobs jobs(home.workspace(), project);
  const auto job = jobs.find(design.id);
  if (!job || job->job_id.empty()) throw Conflict("design " + std::to_string(design.id) + " has no Slurm job to cancel");
  const cluster::Shell shell = cluster_shell(project);
  cluster::cancel(shell, job->job_id);
  // The job's folder comes home once its process is gone, so that status shows where the
  // design stopped (Slurm ends a cancelled job within its KillWait).
  for (int i = 0; i < 120 && !cluster::finished(cluster::job_status(shell, job->job_id).state); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  if (cluster::exists(shell, job->folder + "/design/design.db"))
    cluster::fetch_folder(shell, job->folder + "/design", design.folder);
  storage::Designs(home.workspace(), project).release(design.id, design.owner);
  jobs.observed(design.id, "CANCELLED",
                "Slurm job " + job->job_id + " was cancelled by stop-design; run-design submits it again and it "
                "resumes from its last checkpoint");
  return {design, "cancelled Slurm job " + job->job_id};
}

ClusterCheckReport check_project_cluster(Home& home, const storage::User& user, const std::optional<std::string>& name) {
  ClusterCheckReport report;
  report.project = project_or_active(home, user, name);
  if (!report.project.cluster)
    throw InvalidRequest("project " + report.project.name + " runs on this machine; cluster-check is for a cluster project");
  const cluster::Shell shell = cluster_shell(report.project);
  report.where = shell.describe();
  report.checks = cluster::check_cluster(shell, report.project.cluster->binary_or_default(), version_line(),
                                         report.project.cluster->workdir_or_default());
  return report;
}

}  // namespace sd::app
