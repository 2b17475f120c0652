#include "cli/design_display.hpp"

#include <cstdio>
#include <iostream>

#include "cli/fault_injection.hpp"
#include "control/config_string.hpp"
#include "control/describe.hpp"

namespace sd::cli {

DesignDisplay::DesignDisplay(ProgressLine::Mode mode, bool maximise) : line_(mode), maximise_(maximise) {}

std::string DesignDisplay::line(const design::Progress& p) const {
  char text[256];
  std::snprintf(text, sizeof text, "iteration %d/%d  experiments %lld/%lld  alive %zu/%zu", p.iteration,
                p.nb_iterations, p.experiments_used, p.budget, p.alive, p.race_configurations);
  std::string out = text;
  if (p.best_id > 0)
    out += "  best so far " + format_number(maximise_ ? -p.best_mean : p.best_mean) + " (configuration " +
           std::to_string(p.best_id) + ")";
  return out;
}

void DesignDisplay::progress(const design::Progress& p) {
  line_.show(line(p));
  // A race ended when the next progress belongs to another iteration: log its last step.
  if (have_last_ && p.iteration != last_.iteration) line_.log(line(last_));
  last_ = p;
  have_last_ = true;
}

void DesignDisplay::checkpoint(std::int64_t step) { kill_if_checkpoint(step); }

void DesignDisplay::finish() {
  line_.clear();
  if (line_.mode() == ProgressLine::Mode::Log && have_last_) {
    std::fprintf(stderr, "last race: %s\n", line(last_).c_str());
    std::fflush(stderr);
  }
  have_last_ = false;
}

void print_design_report(const app::DesignReport& r) {
  const app::EliteReport& best = r.elites.front();
  std::cout << "Design finished (" << r.finish_reason << "): " << r.experiments_used << " of " << r.budget
            << " simulation runs, " << r.iterations << " iterations, seed " << r.seed << ".\n"
            << "Best control software (configuration " << best.id << "): mean score " << format_number(best.mean_score)
            << " on " << r.mission << " (" << r.direction << ") over " << best.evaluations << " runs"
            << (r.pseudo_reality.empty() ? "" : " in pseudo-realities " + r.pseudo_reality + " samples " + r.pseudo_reality_samples)
            << "\n"
            << describe(r.best) << "Configuration string:\n  " << best.configuration << "\n"
            << "Design folder: " << r.folder.string() << "\n";
  if (!r.pseudo_reality.empty())
    std::cout << "A robust design: its race ran every candidate in pseudo-realities, not in the design model. Assess it\n"
              << "on samples it never saw: swarmdesign assess --design " << r.folder.string() << " --pseudo-reality "
              << r.pseudo_reality << " --samples 1-20\n";
}

}  // namespace sd::cli
