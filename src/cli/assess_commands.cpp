// Across the reality gap (Ligot & Birattari 2020): `assess` runs control software in the
// design model and in pseudo-realities and reports the drop and the rank changes;
// `pseudo-realities` lists the shipped specifications and shows samples of any of them.
#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/accounts.hpp"
#include "app/assess_job.hpp"
#include "app/assess_sources.hpp"
#include "app/documents.hpp"
#include "app/inputs.hpp"
#include "app/pseudo_realities.hpp"
#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/progress_line.hpp"
#include "control/config_string.hpp"

namespace sd::cli::assess_commands {
namespace {

struct AssessOptions {
  std::string mission, pseudo_reality = "sampled-around", samples = "1-20", seeds = "1-10", csv;
  std::vector<std::string> software, designs, saved;
  std::vector<std::int64_t> project_designs;
  bool elites = false, json = false;
  int threads = 0;
  ControlSoftwareOptions inline_software;
};

/// Every piece of software the command names, labelled; the mission as app::add_software_to_assess sets it.
std::vector<app::SoftwareToAssess> gather_software(const Context& context, const AssessOptions& o, std::string& mission) {
  std::vector<app::SoftwareToAssess> out;
  if (context.has_control_software() || !o.inline_software.config_file.empty())
    out.push_back({"software", read_control_software(context, o.inline_software)});
  for (std::size_t i = 0; i < o.software.size(); ++i)
    out.push_back({"software " + std::to_string(i + 1), parse_control_software(o.software[i])});
  app::Home home;
  // The signed-in user's active project, asked for only when the command names its software.
  std::optional<storage::User> user;
  if (!o.project_designs.empty() || !o.saved.empty()) user = app::signed_in_user(home);
  app::add_software_to_assess(home, user, std::nullopt, {o.designs, o.project_designs, o.saved, o.elites}, out, mission);
  if (out.empty())
    throw UsageError("nothing to assess: give --design DIR, --project-design ID, --saved NAME, --software TEXT or end the "
                     "command with --fsm-config ...");
  return out;
}

std::string percent(double v) {
  if (!std::isfinite(v)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * v);
  return text;
}

void print_assessment(const app::Assessment& a) {
  std::printf("%-36s %10s %10s %24s %7s %8s  %s\n", "SOFTWARE", "DESIGN", "PSEUDO", "DROP [95% CI]", "REL", "p", "RANK");
  for (const auto& s : a.software) {
    char drop[64];
    std::snprintf(drop, sizeof drop, "%.4g [%.4g, %.4g]", s.drop, s.drop_low, s.drop_high);
    std::string label = s.label.size() > 36 ? "..." + s.label.substr(s.label.size() - 33) : s.label;
    std::printf("%-36s %10.4g %10.4g %24s %7s %8.2g  %d -> %d\n", label.c_str(), s.design_mean, s.reality_mean, drop,
                percent(s.relative_drop).c_str(), s.p_value, s.design_rank, s.reality_rank);
  }
  std::printf("Drop: how much worse in the pseudo-realities (positive = a loss); p: paired Wilcoxon signed-rank over seeds.\n");
  if (a.distinct_models < static_cast<int>(a.samples.size()))
    std::printf("%s: its %zu samples are %d distinct model(s)%s; each model ran once.\n", a.spec_reference.c_str(),
                a.samples.size(), a.distinct_models,
                a.distinct_models == 1 ? " (a fixed specification: more samples add nothing)" : "");
  if (a.software.size() >= 2) {
    std::printf("Ranks: %d of %d pair(s) inverted from the design model to the pseudo-realities", a.inverted_pairs, a.pairs);
    if (std::isfinite(a.rank_correlation)) std::printf("; Spearman's rho %.3f", a.rank_correlation);
    std::printf(".\n");
  }
}

void write_csv(const app::Assessment& a, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << app::assessment_csv(a);
}

void register_assess(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand("assess", "Assess control software across the reality gap: design model against pseudo-realities");
  auto o = std::make_shared<AssessOptions>();
  cmd->add_option("--mission", o->mission,
                  "Mission name or mission file (default: the active project's with --project-design or --saved, else the "
                  "first --design's)");
  cmd->add_option("--pseudo-reality", o->pseudo_reality,
                  "Pseudo-reality specification: a shipped name (see `swarmdesign pseudo-realities`) or a .json file "
                  "(default sampled-around)");
  cmd->add_option("--samples", o->samples, "Pseudo-reality samples K or A-B (default 1-20)");
  cmd->add_option("--seeds", o->seeds, "Seeds A-B, the same in every world (default 1-10)");
  cmd->add_option("--software", o->software, "Control software as a configuration string (repeatable)");
  cmd->add_option("--design", o->designs, "A design folder: its best control software (repeatable)");
  cmd->add_option("--project-design", o->project_designs, "A design of the active project, by id: its best (repeatable)");
  cmd->add_option("--saved", o->saved, "Control software saved in the active project, by name (repeatable)");
  cmd->add_flag("--elites", o->elites, "With --design or --project-design: every final elite instead of the best");
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--csv", o->csv, "Write every score (software, world, sample, seed, score) to FILE");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  add_control_software_options(*cmd, o->inline_software);
  cmd->footer(
      "A pseudo-reality is a robot model other than the one the design ran in (the design model), sampled\n"
      "around it: other sensor and actuator noise, packet loss, per-robot deviations. The drop from the design\n"
      "model to the pseudo-realities, and design methods changing ranks, mimic the reality gap in simulation\n"
      "(Ligot & Birattari, Swarm Intelligence 14, 2020).\n\n"
      "Examples:\n"
      "  swarmdesign assess --design aac-1 --design aac-2 --samples 1-50\n"
      "  swarmdesign assess --mission aac --pseudo-reality iridia-transfer --fsm-config --nstates 1 --s0 4 --att0 3");
  cmd->callback([o, &context] {
    std::string mission_name = o->mission;
    app::AssessRequest request;
    request.software = gather_software(context, *o, mission_name);
    if (mission_name.empty()) throw UsageError("--mission is required (or --design DIR)");
    const Mission mission = app::load_requested_mission(mission_name);
    const app::NamedPseudoReality spec = app::load_requested_pseudo_reality(o->pseudo_reality);
    request.spec = spec.spec;
    request.spec_reference = spec.reference;
    request.samples = app::parse_sample_range(o->samples);
    request.seeds = app::parse_seed_range(o->seeds);
    request.threads = o->threads;
    const std::size_t runs = app::assess_runs(request);
    if (!o->json)
      std::printf("Assessing %zu control software on %s: the design model and %zu sample(s) of %s, %zu seed(s) each (%zu runs)\n",
                  request.software.size(), mission.name.c_str(), request.samples.size(), spec.reference.c_str(),
                  request.seeds.size(), runs);
    std::fflush(stdout);
    ProgressLine line(ProgressLine::terminal_if(!o->json));
    request.progress = [&line](std::size_t done, std::size_t all) {
      line.show("assess: " + std::to_string(done) + "/" + std::to_string(all) + " runs");
    };
    const app::Assessment a = app::assess(mission, request);
    line.clear();
    if (!o->csv.empty()) write_csv(a, o->csv);
    if (o->json) {
      std::cout << app::assessment_document(a).dump(2) << "\n";
      return;
    }
    print_assessment(a);
    if (!o->csv.empty()) std::printf("Every score written to %s\n", o->csv.c_str());
  });
}

void register_pseudo_realities(CLI::App& app) {
  auto* cmd = app.add_subcommand("pseudo-realities", "List the shipped pseudo-reality specifications, or show samples of one");
  struct Options {
    std::string name, samples = "1-5", mission = "aac";
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("name", o->name, "A shipped name or a .json file: show its samples");
  cmd->add_option("--samples", o->samples, "With a name: the samples to show (default 1-5)");
  cmd->add_option("--mission", o->mission, "With a name: whose robot model is the design model (default aac)");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  cmd->footer("Example: swarmdesign pseudo-realities sampled-around --samples 1-3");
  cmd->callback([o] {
    if (o->name.empty()) {
      const nlohmann::json list = app::pseudo_realities_document();
      if (o->json) std::cout << list.dump(2) << "\n";
      else
        for (const auto& row : list)
          std::printf("%-22s %s\n", row.at("name").get<std::string>().c_str(), row.at("description").get<std::string>().c_str());
      return;
    }
    const nlohmann::json doc = app::pseudo_reality_samples_document(o->name, o->mission, o->samples);
    std::cout << doc.dump(2) << "\n";
  });
}

const CommandRegistrar registrar{35, [](CLI::App& app, Context& context) {
                                   register_assess(app, context);
                                   register_pseudo_realities(app);
                                 }};

}  // namespace
}  // namespace sd::cli::assess_commands
