// The thesis' three experiments (validation, combination, architecture), the design methods' (methods) and their reports:
// `experiment` runs a protocol in the active project (resuming it when it was interrupted),
// `report` writes its HTML report and CSV files. The jobs are the application layer's (app/experiment_job, app/experiment_report);
// this file parses, prints and shows progress.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/accounts.hpp"
#include "app/design_method.hpp"
#include "app/experiment_job.hpp"
#include "app/cluster_experiments.hpp"
#include "app/experiment_backends.hpp"
#include "app/experiment_report.hpp"
#include "app/protocol_requests.hpp"
#include "app/projects.hpp"
#include "app/inputs.hpp"
#include "cli/command_registry.hpp"
#include "cli/fault_injection.hpp"
#include "cli/progress_line.hpp"
#include "control/config_string.hpp"
#include "design/design_space.hpp"
#include "cli/slurm_flags.hpp"
#include "cli/web_root.hpp"
#include "storage/lease.hpp"

namespace sd::cli::experiment_commands {
namespace {

struct ExperimentOptions {
  std::string name, file, missions, rename, project, seed, pseudo_reality;
  int designs = 0, eval_seeds = 0, samples = 0;
  double budget_scale = 1.0;
  bool evostick = false, dry_run = false, json = false;
  unsigned threads = 0;
  app::ClusterJobRequest job;  // a cluster project's sbatch settings
  CLI::Option *designs_option = nullptr, *eval_seeds_option = nullptr, *scale_option = nullptr, *samples_option = nullptr;
};

std::string duration_text(double seconds) {
  char text[64];
  if (seconds < 120) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 2 * 3600) std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
  else if (seconds < 3 * 86400) std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  else std::snprintf(text, sizeof text, "%.1f days", seconds / 86400);
  return text;
}

/// The flags as the one protocol request every front end fills (app/protocol_requests.hpp).
app::ProtocolRequest protocol_request(const ExperimentOptions& o) {
  app::ProtocolRequest r;
  r.builtin = o.name;
  r.file = o.file;
  r.evostick = o.evostick;
  auto& overrides = r.overrides;
  if (!o.missions.empty()) overrides.missions = design::split_list(o.missions);
  if (o.designs_option->count()) overrides.designs = o.designs;
  if (o.eval_seeds_option->count()) overrides.assessment_seeds = o.eval_seeds;
  if (o.scale_option->count()) overrides.budget_scale = o.budget_scale;
  if (!o.seed.empty()) overrides.seed = app::parse_seed(o.seed);
  if (!o.rename.empty()) overrides.name = o.rename;
  if (!o.pseudo_reality.empty()) overrides.pseudo_reality = o.pseudo_reality;
  if (o.samples_option->count()) overrides.pseudo_reality_samples = o.samples;
  return r;
}

void print_plan(const app::PlannedExperiment& plan) {
  const auto& p = plan.protocol;
  std::cout << "Experiment " << p.name << ": " << p.missions.size() << " missions, " << p.designs
            << " designs per condition, budget scale " << format_number(p.budget_scale) << ", each design assessed on "
            << p.assessment_seeds << " fresh seeds\n";
  if (p.pseudo_reality)
    std::cout << "  and on the same seeds in samples 1-" << p.pseudo_reality->samples << " of pseudo-reality "
              << p.pseudo_reality->spec << " (the reality gap: the drop and the conditions' ranks in the report)\n";
  for (const auto& d : plan.designs)
    if (d.replicate == 1)
      std::cout << "  " << app::mission_label(d.mission) << " / " << d.condition << ": "
                << app::design_method(d.method).describe(d) << ", budget "
                << d.budget << "\n";
  std::cout << "  " << plan.designs.size() << " designs: " << plan.design_runs << " design runs and "
            << plan.assessment_runs << " assessment runs\n";
}

/// What a running experiment shows: one live line for the design being made, one printed line
/// per finished design.
class ExperimentDisplay final : public app::ExperimentObserver {
 public:
  ExperimentDisplay(ProgressLine::Mode mode, bool quiet) : line_(mode), quiet_(quiet) {}

  void design_started(const storage::ExperimentDesign& d, int index, int total) override {
    char text[256];
    std::snprintf(text, sizeof text, "[%d/%d] %s / %s #%d", index, total, app::mission_label(d.plan.mission).c_str(),
                  d.plan.condition.c_str(),
                  d.plan.replicate);
    prefix_ = text;
    line_.show(prefix_ + (d.stage == storage::DesignStage::pending ? "  starting" : "  resuming"));
  }
  void design_reused(const storage::ExperimentDesign& twin, const std::string& experiment) override {
    line_.clear();
    if (!quiet_)
      std::cout << prefix_ << ": the same design as " << experiment << "'s #" << twin.plan.replicate << " of "
                << twin.plan.condition << " (same mission, space, budget and seed): its result is reused\n";
  }
  void design_progress(std::int64_t runs, std::int64_t budget, double best) override {
    line_.show(prefix_ + "  runs " + std::to_string(runs) + "/" + std::to_string(budget) + "  best so far " + format_number(best));
  }
  /// Fault injection counts every checkpoint of this process, whichever design it is in.
  void checkpoint(std::int64_t) override { kill_if_checkpoint(++checkpoints_); }
  void assessing(std::size_t done, std::size_t all) override {
    line_.show(prefix_ + "  assessing " + std::to_string(done) + "/" + std::to_string(all));
  }
  void design_done(const storage::ExperimentDesign&, double score) override {
    line_.clear();
    if (!quiet_) std::cout << prefix_ << ": mean score " << format_number(score) << " on the assessment seeds\n" << std::flush;
  }

 private:
  ProgressLine line_;
  bool quiet_;
  std::string prefix_;
  std::int64_t checkpoints_ = 0;
};

/// A cluster project's experiment: its designs go to Slurm as one job array.
void print_submission(app::Home& home, const storage::User& user, const app::ClusterExperimentSubmission& s,
                      const ExperimentOptions& o) {
  if (o.json) {
    std::cout << app::experiments_document(app::experiments_progress(home, user, s.project.name)).dump(2) << "\n";
    return;
  }
  const std::string& name = s.experiment.name;
  if (s.experiment.state == storage::DesignState::finished) {
    std::cout << "Experiment " << name << " of " << s.project.name << " has finished (" << s.designs_done << " designs"
              << (s.designs_reused ? ", " + std::to_string(s.designs_reused) + " reused from other experiments" : "")
              << ").\nReport it with: swarmdesign report " << name << "\n";
    return;
  }
  if (s.still_running) {
    std::cout << "Experiment " << name << " of " << s.project.name << " still runs as Slurm array job "
              << (s.job ? s.job->job_id : "?") << ": " << s.designs_done << " of " << s.designs << " designs done.\n"
              << "  watch it:  swarmdesign status\n";
    return;
  }
  std::cout << "Experiment " << name << " of " << s.project.name << ": " << s.designs_submitted << " of " << s.designs
            << " designs submitted to Slurm as array job " << s.job->job_id << " on " << s.where << " (folder "
            << s.job->folder << ")";
  if (s.designs_done) std::cout << "; " << s.designs_done << " already done";
  std::cout << ".\nEach design comes home when its task ends and is assessed here.\n"
            << "  watch it:  swarmdesign status\n  then:      swarmdesign report " << name << "\n";
}

/// `--dry-run`: the plan and its time here (app::plan_with_estimate, as the page's Plan).
void print_estimate(const ExperimentOptions& o) {
  const app::EstimatedPlan planned = app::plan_with_estimate(protocol_request(o), app::FileScope::local(), o.threads);
  for (const auto& note : planned.plan.notes) std::cerr << "swarmdesign: note: " << note << "\n";
  if (o.json) {
    std::cout << app::estimated_plan_document(planned).dump(2) << "\n";
    return;
  }
  const app::DurationEstimate& estimate = *planned.estimate;
  print_plan(planned.plan);
  std::cout << "On this machine (" << estimate.threads << " threads, speed measured now):\n";
  for (const auto& m : estimate.missions)
    std::cout << "  " << m.mission << ": " << m.runs << " runs at " << format_number(std::round(m.seconds_per_run * 1e5) / 100)
              << " ms per run = " << duration_text(m.seconds_per_run * static_cast<double>(m.runs)) << "\n";
  std::cout << "  in all about " << duration_text(estimate.seconds) << " (simulation only; the optimiser adds a little)\n";
}

void run_experiment_command(const ExperimentOptions& o) {
  if (o.dry_run) return print_estimate(o);
  // Where it runs is the project's experiment backend's (a cluster project's: a Slurm array).
  const app::LaunchedExperiment launched = [&] {
    app::Home home;
    const auto user = app::signed_in_user(home);
    app::LaunchedExperiment l = app::launch_experiment(
        home, user, {protocol_request(o), o.project.empty() ? std::nullopt : std::optional(o.project), app::FileScope::local(),
                     o.job, o.threads});
    for (const auto& note : l.plan.notes) std::cerr << "swarmdesign: note: " << note << "\n";
    if (l.slurm) print_submission(home, user, *l.slurm, o);
    return l;
  }();
  if (launched.where == app::ExperimentWhere::slurm) return;
  const app::PlannedExperiment& plan = launched.plan;
  app::StartedExperiment started = launched.started;
  const std::string& name = started.experiment.name;
  if (!o.json) {
    if (started.already_finished) std::cout << "Experiment " << name << " of " << started.project.name << " has already finished.\n";
    else if (started.resumed) std::cout << "Experiment " << name << " of " << started.project.name << " was interrupted; resuming it.\n";
    else print_plan(plan);
  }
  ExperimentDisplay display(ProgressLine::terminal_if(!o.json), o.json);
  const app::ExperimentOutcome outcome = app::run_experiment(started, {.threads = o.threads, .evaluator = nullptr,
                                                                       .observer = &display, .cancel = nullptr});
  if (o.json) {
    app::Home home;
    std::cout << app::experiments_document(app::experiments_progress(home, app::signed_in_user(home), started.project.name))
                     .dump(2)
              << "\n";
    return;
  }
  if (!started.already_finished)
    std::cout << "Experiment " << name << " finished: " << outcome.designs_done << " designs in "
              << duration_text(outcome.wall_seconds) << (started.resumed ? " (this session)" : "") << ".\n";
  std::cout << "Report it with: swarmdesign report " << name << "\n";
}

struct ReportOptions {
  std::string experiment, out, project;
  std::string web_root = default_web_root();
  bool json = false;
};

/// The headline: per mission and condition the median design score, and the Friedman test.
void print_headline(const nlohmann::json& doc) {
  for (const auto& box : doc["boxes"])
    std::cout << "  " << box["mission"].get<std::string>() << " / " << box["condition"].get<std::string>() << ": median "
              << format_number(box["median"].get<double>()) << " over " << box["n"] << " designs (IQR "
              << format_number(box["q1"].get<double>()) << " to " << format_number(box["q3"].get<double>()) << ")\n";
  for (const auto& w : doc["wilcoxon"])
    if (!w["better"].is_null())
      std::cout << "  " << w["mission"].get<std::string>() << ": " << w["better"].get<std::string>()
                << " is better (Wilcoxon rank-sum p = " << format_number(w["p_value"].get<double>()) << ")\n";
  if (const auto& r = doc.value("pseudo_reality", nlohmann::json(nullptr)); r.is_object()) {
    std::cout << "  In pseudo-reality " << r["spec"].get<std::string>() << " (samples 1-" << r["samples"] << "):\n";
    for (const auto& c : r["cells"])
      std::cout << "    " << c["mission"].get<std::string>() << " / " << c["condition"].get<std::string>() << ": median "
                << format_number(c["pseudo_reality"]["median"].get<double>()) << " (design model "
                << format_number(c["design_model"]["median"].get<double>()) << "), median drop "
                << format_number(std::round(c["median_drop"].get<double>() * 1e4) / 1e4) << ", paired Wilcoxon p = "
                << (c["wilcoxon"].is_null() ? std::string("n/a") : format_number(c["wilcoxon"]["p_value"].get<double>())) << "\n";
    for (const auto& i : r["inversions"])
      std::cout << "    " << i["mission"].get<std::string>() << ": " << i["a"].get<std::string>() << " and "
                << i["b"].get<std::string>() << " change ranks in the pseudo-realities\n";
  }
  if (const auto& f = doc["friedman"]; !f.is_null()) {
    std::cout << "  Friedman across missions: p = " << (f["p_value"].is_null() ? "n/a" : format_number(f["p_value"].get<double>()))
              << "; expected ranks:";
    for (const auto& r : f["expected_ranks"])
      std::cout << " " << r["condition"].get<std::string>() << " " << format_number(r["rank"].get<double>());
    std::cout << "\n";
  }
}

void report_command(const ReportOptions& o) {
  app::Home home;
  // A report is asked for its results: a cluster experiment's finished designs come home first.
  app::collect_cluster_experiments(home, app::signed_in_user(home), o.project.empty() ? std::nullopt : std::optional(o.project));
  const nlohmann::json doc = app::experiment_report_document(home, app::signed_in_user(home), o.experiment,
                                                             o.project.empty() ? std::nullopt : std::optional(o.project));
  const std::filesystem::path out = o.out.empty() ? "report-" + o.experiment : o.out;
  const auto files = app::write_experiment_report(doc, out, o.web_root);
  if (o.json) {
    std::cout << doc.dump(2) << "\n";
    return;
  }
  const auto& e = doc["experiment"];
  std::cout << "Report of experiment " << e["name"].get<std::string>() << " (" << e["state"].get<std::string>() << ", "
            << e["designs_done"] << " of " << e["designs_planned"] << " designs done)\n";
  print_headline(doc);
  std::cout << "Written: " << (out / "report.html").string() << " (open it in a browser; it needs no network) and "
            << files.size() - 2 << " CSV files in " << out.string() << "\n";
}

struct CollectOptions {
  std::string project;
  unsigned threads = 0;
  bool json = false;
};

void collect_command(const CollectOptions& o) {
  app::Home home;
  const auto user = app::signed_in_user(home);
  const std::optional<std::string> project = o.project.empty() ? std::nullopt : std::optional(o.project);
  const storage::Project p = app::project_or_active(home, user, project);
  if (!p.cluster && !o.json) {
    std::cout << "Project " << p.name << " runs on this machine: its experiments' designs are already here.\n";
    return;
  }
  const app::ClusterCollection c = app::collect_cluster_experiments(home, user, p.name, o.threads);
  if (o.json) {
    std::cout << app::collection_document(p.name, c, app::experiments_progress(home, user, p.name)).dump(2) << "\n";
    return;
  }
  if (c.experiments == 0) {
    std::cout << "Project " << p.name << " has no experiment running on the cluster.\n";
    return;
  }
  std::cout << c.designs_home << " design" << (c.designs_home == 1 ? "" : "s") << " came home and " << (c.designs_home == 1 ? "was" : "were")
            << " assessed; " << c.still_running << " of " << c.experiments << " experiment" << (c.experiments == 1 ? "" : "s")
            << " still running on the cluster.\n  see them: swarmdesign status\n";
}

CommandRegistrar registrar{45, [](CLI::App& app, Context&) {
  auto o = std::make_shared<ExperimentOptions>();
  auto* cmd = app.add_subcommand("experiment", "Run one of the thesis' experiments (or your own protocol) in the active project");
  cmd->add_option("name", o->name, "validation | combination | architecture | methods");
  cmd->add_option("--file", o->file, "Run your own protocol (a JSON file; see src/experiments/README.md)");
  cmd->add_option("--missions", o->missions, "Only these missions, comma-separated (e.g. aac,foraging)");
  o->designs_option = cmd->add_option("--designs", o->designs, "Independent designs per mission and condition (default 10)");
  o->scale_option =
      cmd->add_option("--budget-scale", o->budget_scale, "Multiply every budget (e.g. 0.05 for a quick look; default 1)");
  o->eval_seeds_option =
      cmd->add_option("--assessment-seeds,--eval-seeds", o->eval_seeds,
                      "Fresh seeds each final design is assessed on (default 20; the protocol's and the page's "
                      "assessment_seeds; --eval-seeds is its first name, kept for one release)");
  cmd->add_option("--seed", o->seed, "Seed every design's seed derives from (default 1)");
  cmd->add_option("--name", o->rename, "Store it under another name (to keep several variants of one protocol)");
  cmd->add_option("--pseudo-reality", o->pseudo_reality,
                  "Also assess every final design in this pseudo-reality (a shipped name, see swarmdesign "
                  "pseudo-realities, or a file)");
  o->samples_option = cmd->add_option("--pseudo-reality-samples", o->samples,
                                      "Pseudo-reality samples 1..N each design also runs in (default 20)");
  cmd->add_flag("--evostick", o->evostick, "Add the EvoStick baseline as a further condition on every mission");
  cmd->add_option("--project", o->project, "Run it in this project (default: the active one)");
  cmd->add_option("--threads", o->threads, "Simulations in parallel (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--dry-run", o->dry_run, "Print what would run and how long it would take here, and stop");
  cmd->add_flag("--json", o->json, "Print JSON documents instead of text");
  add_slurm_flags(*cmd, o->job);
  cmd->footer(
      "The thesis' three experiments, on its missions and budgets (aac 200 000, foraging 50 000,\n"
      "tutti-aggregation 100 000, grid-exploration 100 000, aggregation-xor 200 000):\n"
      "  validation    each flavour alone on its own mission (Maple with behaviour trees)\n"
      "  combination   that, against all five flavours with both architectures\n"
      "  architecture  all five flavours as finite-state machines against behaviour trees, budget 200 000\n"
      "  methods       the design methods (automode, random-search, local-search) on each mission's own\n"
      "                flavour and on the combined space, budget 20 000 (--budget-scale 5: 100 000)\n"
      "Designs run one after the other on all cores; every design and assessment is stored in the\n"
      "project as it ends. Killed, the same command resumes it inside the design it was in and ends\n"
      "with the same results. Budgets below the optimiser's minimum are raised to it (with a note).\n"
      "In a cluster project the designs go to Slurm as one job array (one task per design, with the\n"
      "Slurm options above); each comes home when its task ends and is assessed here. Run the same\n"
      "command again to submit what a cut-short array left: those designs resume.\n"
      "With --pseudo-reality (or \"pseudo_reality\": {\"spec\": ..., \"samples\": N} in a protocol file)\n"
      "each final design also runs on its assessment seeds in pseudo-reality samples 1..N (robot\n"
      "models drawn around the design model, Ligot & Birattari 2020); the report then shows each\n"
      "condition's scores in both side by side, the drop with its test, and how the conditions'\n"
      "ranks change. --json lists each experiment's pseudo_reality.\n\n"
      "Examples:\n  swarmdesign experiment validation --dry-run\n"
      "  swarmdesign experiment combination --missions aac,foraging --designs 3 --budget-scale 0.05\n"
      "  swarmdesign experiment --file my-protocol.json\n"
      "  swarmdesign experiment validation --missions aac --designs 5 --pseudo-reality sampled-around");
  cmd->callback([o] { run_experiment_command(*o); });

  auto r = std::make_shared<ReportOptions>();
  auto* report = app.add_subcommand("report", "Write an experiment's report: HTML (opens offline) and CSV files");
  report->add_option("experiment", r->experiment, "The experiment's name (as status lists them)")->required();
  report->add_option("--out", r->out, "Folder to write into (default: ./report-EXPERIMENT)");
  report->add_option("--project", r->project, "The experiment's project (default: the active one)");
  report->add_option("--web-root", r->web_root, "Folder of the built front end (report.js)")->capture_default_str();
  report->add_flag("--json", r->json, "Also print the report document (every number) on stdout");
  report->footer(
      "The report holds notched box plots of the design scores per mission and condition, Wilcoxon\n"
      "rank-sum tests per mission, the Friedman test across missions with expected ranks, heat maps\n"
      "of the modules the designs use, the architecture each chose, convergence curves, the best and\n"
      "the median design drawn, and wall time; each table is also a CSV file. An unfinished\n"
      "experiment is reported as far as it went.\n\n"
      "Example:\n  swarmdesign report validation --out validation-report");
  report->callback([r] { report_command(*r); });

  auto c = std::make_shared<CollectOptions>();
  auto* collect = app.add_subcommand("collect", "Bring a cluster project's finished experiment designs home and assess them");
  collect->add_option("--project", c->project, "The cluster project (default: the active one)");
  collect->add_option("--threads", c->threads, "Simulations in parallel for the assessments (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  collect->add_flag("--json", c->json, "Print what was collected and the experiments' progress as JSON");
  collect->footer(
      "A cluster experiment's designs are made by Slurm array tasks; each comes home when its task\n"
      "ends and is assessed here on the experiment's fresh seeds. status only reads what is here (a\n"
      "poll starts no work), so run collect to bring results in; report and experiment collect\n"
      "first, and the web server collects the projects its pages show every 20 s.\n\n"
      "Example:\n  swarmdesign collect && swarmdesign status");
  collect->callback([c] { collect_command(*c); });
}};

}  // namespace
}  // namespace sd::cli::experiment_commands
