#include "cli/score_output.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

#include "app/documents.hpp"
#include "app/evaluation_job.hpp"
#include "cli/progress_line.hpp"
#include "control/config_string.hpp"

namespace sd::cli {

void score_and_print(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                     int threads, bool json) {
  ProgressLine line(ProgressLine::terminal_if(!json && seeds.size() > 1));
  app::ScoreOptions options;
  options.threads = threads;
  if (line.mode() != ProgressLine::Mode::Off)
    options.progress = [&](std::size_t done, std::size_t total) {
      line.show("evaluated " + std::to_string(done) + "/" + std::to_string(total) + " seeds");
    };
  const auto scores = app::score_seeds(mission, software, seeds, options);
  line.clear();
  print_scores(mission, software, seeds, scores, json);
}

void print_scores(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                  const std::vector<double>& scores, bool json) {
  if (json) {
    std::cout << app::scores_document(mission, software, seeds, scores).dump(2) << "\n";
    return;
  }
  for (const double score : scores) std::cout << "Score " << format_number(score) << "\n";
  if (seeds.size() > 1) {
    const app::ScoreSummary summary = app::summarize(scores);
    std::cout << "Mean " << format_number(summary.mean) << "\nMedian " << format_number(summary.median) << "\n";
  }
}

}  // namespace sd::cli
