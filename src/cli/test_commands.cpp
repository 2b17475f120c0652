// Scoring designs on fresh seeds: `test-design` (a design's best, or given control software) and
// `compare-designs A B` (two designs' bests on the same seeds, with the paired test). The
// services are the application layer's (app/test_design), shared with the web's /test and
// /compare and with Python; this file parses, shows progress and prints.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <optional>

#include "app/accounts.hpp"
#include "app/inputs.hpp"
#include "app/test_design.hpp"
#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/export_display.hpp"
#include "cli/progress_line.hpp"
#include "cli/score_output.hpp"
#include "control/config_string.hpp"

namespace sd::cli::test_commands {
namespace {

using nlohmann::json;

/// Shows "evaluated N/M runs" while scoring, on a terminal only.
std::function<void(std::size_t, std::size_t)> progress_on(ProgressLine& line) {
  if (line.mode() == ProgressLine::Mode::Off) return {};
  return [&line](std::size_t done, std::size_t all) {
    line.show("evaluated " + std::to_string(done) + "/" + std::to_string(all) + " runs");
  };
}

void print_summary(const json& doc, const std::string& indent) {
  if (doc.contains("mean"))
    std::cout << indent << "Mean " << format_number(doc["mean"].get<double>()) << "\n"
              << indent << "Median " << format_number(doc["median"].get<double>()) << "\n";
  if (!doc["sd"].is_null()) std::cout << indent << "Standard deviation " << format_number(doc["sd"].get<double>()) << "\n";
}

struct TestDesignOptions {
  std::string seeds = "1-10", project;
  std::int64_t design = 0;
  int threads = 0;
  bool json = false, argos = false;
  ControlSoftwareOptions software;
};

void test_design(const TestDesignOptions& o, const Context& context) {
  if (o.argos && o.json)
    throw UsageError("--argos prints a text line; leave out --json (or use: swarmdesign export --argos --json)");
  app::TestDesignRequest request;
  request.seeds = o.seeds;
  request.threads = o.threads;
  if (!o.project.empty()) request.project = o.project;
  if (o.design > 0) request.design = o.design;
  if (context.has_control_software() || !o.software.config_file.empty()) request.software = read_control_software(context, o.software);
  if (request.software && request.design) throw UsageError("give --design or control software to test, not both");
  app::Home home;
  ProgressLine line(ProgressLine::terminal_if(!o.json && app::parse_seed_range(o.seeds).size() > 1));
  request.progress = progress_on(line);
  const json doc = app::test_design(home, app::signed_in_user(home), request);
  line.clear();
  if (o.json) {
    std::cout << doc.dump(2) << "\n";
    return;
  }
  if (!doc["design"].is_null())
    std::cout << "Testing the best control software of design " << doc["design"] << " (on its own mission, "
              << doc["mission"].get<std::string>() << "):\n  " << doc["control_software"].get<std::string>() << "\n";
  if (o.argos) print_argos_line(parse_control_software(doc["control_software"].get<std::string>()), "  ", "");
  for (const json& run : doc["runs"]) std::cout << "Score " << format_number(run["score"].get<double>()) << "\n";
  print_summary(doc, "");
}

struct CompareOptions {
  std::int64_t a = 0, b = 0;
  std::string seeds = "1-20", project;
  int threads = 0;
  bool json = false;
};

void compare_designs(const CompareOptions& o) {
  app::CompareDesignsRequest request;
  request.a = o.a;
  request.b = o.b;
  request.seeds = o.seeds;
  request.threads = o.threads;
  if (!o.project.empty()) request.project = o.project;
  app::Home home;
  ProgressLine line(ProgressLine::terminal_if(!o.json));
  request.progress = progress_on(line);
  const json doc = app::compare_designs(home, app::signed_in_user(home), request);
  line.clear();
  if (o.json) {
    std::cout << doc.dump(2) << "\n";
    return;
  }
  std::cout << "On seeds " << doc["seeds"].get<std::string>() << ":\n";
  for (const json& side : doc["designs"]) {
    std::cout << "  design " << side["design"] << " (" << side["mission"].get<std::string>() << "): "
              << side["control_software"].get<std::string>() << "\n";
    print_summary(side, "    ");
  }
  const json& w = doc["wilcoxon"];
  if (w.contains("note")) {
    std::cout << "  " << w["test"].get<std::string>() << ": " << w["note"].get<std::string>() << "\n";
    return;
  }
  std::cout << "  " << w["test"].get<std::string>() << ": p = " << format_number(w["p_value"].get<double>())
            << ", estimated difference " << format_number(w["estimate"].get<double>()) << " (design " << o.a
            << " minus design " << o.b << ")\n";
}

CommandRegistrar registrar{41, [](CLI::App& app, Context& context) {
  auto test = std::make_shared<TestDesignOptions>();
  auto* tcmd = app.add_subcommand("test-design", "Evaluate a design's best (or given control software) on fresh seeds");
  tcmd->alias("testDesign");
  tcmd->add_option("--seeds", test->seeds, "Seeds A-B to evaluate on (default 1-10)");
  tcmd->add_option("--design", test->design, "This design's best (default: the project's last design with one)")
      ->check(CLI::PositiveNumber);
  tcmd->add_option("--project", test->project, "The project (default: the active one)");
  tcmd->add_option("--threads", test->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  tcmd->add_flag("--json", test->json, "Print one JSON document");
  tcmd->add_flag("--argos", test->argos, "Also print the control software as ARGoS3-AutoMoDe reads it (export --argos)");
  add_control_software_options(*tcmd, test->software);
  tcmd->footer(
      "Without control software, tests the best control software of the project's last design that has\n"
      "one (or of --design), on that design's own mission. Given control software runs on the project's\n"
      "mission. The control software ends the command line. The web's Test and Python's test_design\n"
      "give the same document as --json.\n\n"
      "Example:\n  swarmdesign test-design --seeds 1-20\n  swarmdesign test-design --design 3 --json\n"
      "  swarmdesign test-design --seeds 1-20 --fsm-config --nstates 1 --s0 10 --rwm0 50\n"
      "  swarmdesign test-design --argos");
  tcmd->callback([test, &context] { test_design(*test, context); });

  auto compare = std::make_shared<CompareOptions>();
  auto* ccmd = app.add_subcommand("compare-designs", "Compare two designs' bests on the same fresh seeds, with a paired test");
  ccmd->add_option("a", compare->a, "The first design's number")->required()->check(CLI::PositiveNumber);
  ccmd->add_option("b", compare->b, "The second design's number")->required()->check(CLI::PositiveNumber);
  ccmd->add_option("--seeds", compare->seeds, "Seeds A-B both run on (default 1-20)");
  ccmd->add_option("--project", compare->project, "The designs' project (default: the active one)");
  ccmd->add_option("--threads", compare->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  ccmd->add_flag("--json", compare->json, "Print one JSON document (the web's Compare gives the same)");
  ccmd->footer(
      "Each design's best runs on its own mission, both on the same seeds; the Wilcoxon signed-rank test,\n"
      "paired by seed, says whether one is better (an experiment's report uses the same test).\n\n"
      "Example:\n  swarmdesign compare-designs 1 2 --seeds 1-50");
  ccmd->callback([compare] { compare_designs(*compare); });
}};

}  // namespace
}  // namespace sd::cli::test_commands
