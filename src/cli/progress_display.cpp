#include "cli/progress_display.hpp"

#include <cstdio>
#include <ctime>

#include "control/config_string.hpp"

namespace sd::cli {

std::string ProgressDisplay::line(const design::Progress& p) const {
  char text[256];
  std::snprintf(text, sizeof text, "iteration %d/%d  experiments %lld/%lld  alive %zu/%zu", p.iteration,
                p.nb_iterations, p.experiments_used, p.budget, p.alive, p.race_configurations);
  std::string out = text;
  if (p.best_id > 0)
    out += "  best so far " + format_number(maximise_ ? -p.best_mean : p.best_mean) + " (configuration " +
           std::to_string(p.best_id) + ")";
  return out;
}

void ProgressDisplay::update(const design::Progress& p) {
  if (mode_ == Mode::Terminal) {
    std::fprintf(stderr, "\r\033[K%s", line(p).c_str());
    std::fflush(stderr);
    shown_ = true;
  } else if (mode_ == Mode::Log) {
    // A race ended when the next progress belongs to another iteration: log the last step.
    if (have_last_ && p.iteration != last_.iteration) {
      const std::time_t now = std::time(nullptr);
      char stamp[32];
      std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
      std::fprintf(stderr, "%s  %s\n", stamp, line(last_).c_str());
      std::fflush(stderr);
    }
    last_ = p;
    have_last_ = true;
  }
}

void ProgressDisplay::clear() {
  if (mode_ == Mode::Terminal && shown_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
  }
  if (mode_ == Mode::Log && have_last_) {
    std::fprintf(stderr, "last race: %s\n", line(last_).c_str());
    std::fflush(stderr);
    have_last_ = false;
  }
}

}  // namespace sd::cli
