#pragma once
// What a running design shows: a line rewritten in place on a terminal, or one line per
// finished iteration in a log file (a detached design).
#include <string>

#include "design/iterated_race.hpp"

namespace sd::cli {

class ProgressDisplay {
 public:
  enum class Mode { Off, Terminal, Log };
  /// `maximise`: best costs are shown as the mission's scores (-cost).
  ProgressDisplay(Mode mode, bool maximise) : mode_(mode), maximise_(maximise) {}
  ~ProgressDisplay() { clear(); }

  void update(const design::Progress& p);
  /// Removes the live line before the final report.
  void clear();

 private:
  std::string line(const design::Progress& p) const;

  Mode mode_;
  bool maximise_;
  bool shown_ = false;
  design::Progress last_{};
  bool have_last_ = false;
};

}  // namespace sd::cli
