// The calibration against ARGoS with SwarmDesign's own seed noise taken out: every controller of
// the calibration set (src/evaluation/argos_reference.hpp; ARGoS seeds 1-20) runs here on seeds
// 1..N, so that a difference the calibration test's 20 seeds against 20 cannot tell from seed
// luck shows, and one it flags by luck does not. Per controller: both means, the ratio, the
// difference in ARGoS standard deviations and Welch's t (the difference over its standard error);
// per group: Spearman's rho, the median ratio, the controllers above and below ARGoS, and
// Stouffer's combined z (the controllers' t summed over the square root of their number), which
// tests a whole mission for a lean in one direction. Run with --help for the options.
//
// With --start-matched the comparison is start-matched instead, on the groups whose ARGoS start
// placements are known (tests/data/argos-starts/): for each ARGoS seed with a known start, the
// controller runs here from that placement on noise seeds 1..N, and its mean is paired with
// ARGoS' score on that seed (paired t, and Stouffer's z of the paired tests' normal scores).
// ARGoS' 20 placements are a sample too; matching them takes that sample out of the comparison.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <fstream>
#include <string>
#include <vector>

#include "control/config_string.hpp"
#include "evaluation/argos_reference.hpp"
#include "evaluation/evaluator.hpp"
#include "statistics/correlation.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/paired_t.hpp"
#include "statistics/stouffer.hpp"
#include "statistics/welch.hpp"

namespace {

using namespace sd;

using statistics::mean;
using statistics::sample_standard_deviation;

nlohmann::json compare_group(const ArgosReferenceGroup& group, const std::string& data, int seeds, ThreadedEvaluator& evaluator) {
  const Mission mission = argos_reference_mission(group);
  ArgosAgreement agreement;
  double largest = 0.0;
  std::vector<double> welch_t;  // per controller, an undefined t (both samples constant) as 0
  nlohmann::json rows = nlohmann::json::array();
  const std::vector<ArgosReferenceController> refs = read_argos_reference(data, group);
  for (const ArgosReferenceController& ref : refs) {
    const ControlSoftware software = parse_control_software(ref.config, {ref.legacy_flavour});
    std::vector<EvaluationTask> tasks;
    for (int seed = 1; seed <= seeds; ++seed) tasks.push_back({&software, static_cast<std::uint64_t>(seed)});
    std::vector<double> scores(tasks.size());
    evaluator.evaluate(mission, tasks, scores);
    const double ours = mean(scores), theirs = mean(ref.scores), spread = sample_standard_deviation(ref.scores);
    const double t = statistics::welch_t_test(scores, ref.scores).statistic;
    const double deviation = spread > 0 ? (ours - theirs) / spread : 0.0;
    welch_t.push_back(std::isfinite(t) ? t : 0.0);
    largest = std::max(largest, std::abs(deviation));
    agreement.add(ours, theirs);
    std::printf("%-18s %-4s argos %10.2f (sd %9.2f)  ours %10.2f (sd %9.2f)  ratio %6.2f  dev %+6.2f sd  t %+6.2f\n", group.name,
                ref.name.c_str(), theirs, spread, ours, sample_standard_deviation(scores), theirs != 0 ? ours / theirs : NAN, deviation, t);
    std::fflush(stdout);
    rows.push_back({{"controller", ref.name}, {"argos_mean", theirs}, {"argos_sd", spread}, {"ours_mean", ours},
                    {"ours_sd", sample_standard_deviation(scores)}, {"deviation_sd", deviation}, {"welch_t", t}});
  }
  const auto [z, p] = statistics::stouffer_z(welch_t);
  const double rho = statistics::spearman_rho(agreement.ours, agreement.argos);
  const double median_ratio = agreement.ratios.empty() ? NAN : statistics::median(agreement.ratios);
  std::printf("== %s: %zu controllers, seeds 1-%d: rho %.3f  median ratio %.3f  max |dev| %.2f sd  above %d below %d  "
              "Stouffer z %+.2f (p %.4f)\n",
              group.name, refs.size(), seeds, rho, median_ratio, largest, agreement.above, agreement.below, z, p);
  return {{"group", group.name}, {"controllers", refs.size()}, {"spearman_rho", rho}, {"median_ratio", median_ratio},
          {"max_abs_deviation_sd", largest}, {"above", agreement.above}, {"below", agreement.below}, {"stouffer_z", z}, {"stouffer_p", p},
          {"rows", rows}};
}

nlohmann::json compare_group_start_matched(const ArgosReferenceGroup& group, const std::string& data, int seeds,
                                           ThreadedEvaluator& evaluator) {
  const std::vector<ArgosReferenceController> refs = read_argos_reference(data, group);
  const std::vector<ArgosStart> starts = argos_starts(data, group, refs.empty() ? 0 : static_cast<int>(refs.front().scores.size()));
  ArgosAgreement agreement;
  std::vector<double> z_scores;
  nlohmann::json rows = nlohmann::json::array();
  for (const ArgosReferenceController& ref : refs) {
    const ControlSoftware software = parse_control_software(ref.config, {ref.legacy_flavour});
    std::vector<double> ours, theirs;
    for (const auto& [seed, mission] : starts) {
      std::vector<EvaluationTask> tasks;
      for (int noise = 1; noise <= seeds; ++noise) tasks.push_back({&software, static_cast<std::uint64_t>(noise)});
      std::vector<double> scores(tasks.size());
      evaluator.evaluate(mission, tasks, scores);
      const double argos = ref.scores.at(static_cast<std::size_t>(seed - 1));
      // A mean equal to ARGoS' but in its last bit (0.05 summed 40 times) is equal: the paired t
      // of such rounding alone is huge (C02, which never moves, gave t +7.18 on aggregation180).
      const double here = mean(scores);
      ours.push_back(std::abs(here - argos) <= 1e-9 * std::max(1.0, std::abs(argos)) ? argos : here);
      theirs.push_back(argos);
    }
    const statistics::PairedTest test = statistics::paired_t_test(ours, theirs);
    const double z = std::isfinite(test.z) ? test.z : 0.0;
    const double ours_mean = mean(ours), argos_mean = mean(theirs);
    z_scores.push_back(z);
    agreement.add(ours_mean, argos_mean);
    std::printf("%-18s %-4s %zu starts  argos %10.2f  ours %10.2f  ratio %6.2f  paired t %+6.2f (df %.0f, p %.3f)  z %+5.2f\n",
                group.name, ref.name.c_str(), starts.size(), argos_mean, ours_mean,
                argos_mean != 0 ? ours_mean / argos_mean : NAN, test.statistic, test.df, test.p_value, z);
    std::fflush(stdout);
    rows.push_back({{"controller", ref.name}, {"argos_mean", argos_mean}, {"ours_mean", ours_mean},
                    {"paired_t", test.statistic}, {"df", test.df}, {"p_value", test.p_value}, {"z", z}});
  }
  const auto [z, p] = statistics::stouffer_z(z_scores);
  const double median_ratio = agreement.ratios.empty() ? NAN : statistics::median(agreement.ratios);
  std::printf("== %s start-matched: %zu controllers, %zu ARGoS starts x noise seeds 1-%d: median ratio %.3f  above %d "
              "below %d  Stouffer z %+.2f (p %.4f)\n",
              group.name, refs.size(), starts.size(), seeds, median_ratio, agreement.above, agreement.below, z, p);
  return {{"group", group.name}, {"start_matched", true}, {"starts", starts.size()}, {"controllers", refs.size()},
          {"median_ratio", median_ratio}, {"above", agreement.above}, {"below", agreement.below}, {"stouffer_z", z},
          {"stouffer_p", p}, {"rows", rows}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The ARGoS calibration set run on seeds 1..N here (ARGoS' side has seeds 1-20): per controller the\n"
               "means, ratio, deviation in ARGoS sd and Welch's t; per mission Spearman's rho, the median ratio and\n"
               "Stouffer's z (|z| > 2.58: the mission leans one way at p < 1 %). About 4 minutes for 200 seeds on 2 cores."};
  int seeds = 200, threads = 0;
  std::vector<std::string> only;
  std::string json_path, data = SWARMDESIGN_CALIBRATION_DATA;
  app.add_option("--seeds", seeds, "Seeds per controller on SwarmDesign's side, 1..N (default 200)")->check(CLI::Range(2, 100000));
  std::vector<std::string> names;
  for (const ArgosReferenceGroup& g : argos_reference_groups()) names.emplace_back(g.name);
  app.add_option("--group", only, "Only these groups (repeatable)")->check(CLI::IsMember(names));
  app.add_option("--threads", threads, "Simulations in parallel (default: all cores)")->check(CLI::NonNegativeNumber);
  app.add_option("--data", data, "Folder of argos-reference*.csv (default: the repository's tests/data)");
  app.add_option("--json", json_path, "Also write every figure to FILE as one JSON document");
  bool start_matched = false;
  app.add_flag("--start-matched", start_matched,
               "Start-matched: run from ARGoS' own start placement of each seed where it is known (the data folder's\n"
               "argos-starts/; groups without any are left out), paired seed by seed. --seeds is then the noise seeds per start");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) {
      std::fprintf(stderr, "calibration_wide: error: %s (see --help)\n", e.what());
      return 2;
    }
    return app.exit(e);
  }
  try {
    std::ofstream out;  // opened first: a wrong path fails before minutes of runs, not after
    if (!json_path.empty()) {
      out.open(json_path);
      if (!out) throw std::runtime_error("cannot write " + json_path);
    }
    ThreadedEvaluator evaluator(threads);
    nlohmann::json report{{"seeds", seeds}, {"groups", nlohmann::json::array()}};
    for (const ArgosReferenceGroup& group : argos_reference_groups()) {
      if (!only.empty() && std::find(only.begin(), only.end(), group.name) == only.end()) continue;
      if (!start_matched) {
        report["groups"].push_back(compare_group(group, data, seeds, evaluator));
      } else if (*group.argos_starts) {
        report["groups"].push_back(compare_group_start_matched(group, data, seeds, evaluator));
      }
    }
    if (!json_path.empty() && !(out << report.dump(1) << '\n')) throw std::runtime_error("cannot write " + json_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "calibration_wide: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
