#pragma once
// The one progress display of every long command (design, run-design, evaluate --seeds,
// evostick): a line rewritten in place on a terminal, or — for a detached design writing to a
// log file — a time-stamped line per milestone. Nothing at all with --json or when stderr is
// not a terminal.
#include <string>

namespace sd::cli {

class ProgressLine {
 public:
  enum class Mode { Off, Terminal, Log };
  /// Terminal when stderr is one and `wanted`, else Off.
  static Mode terminal_if(bool wanted);

  explicit ProgressLine(Mode mode) : mode_(mode) {}
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// The live line (Terminal); ignored in the other modes.
  void show(const std::string& text);
  /// A milestone: a time-stamped line (Log); ignored in the other modes.
  void log(const std::string& text);
  /// Removes the live line before a final report.
  void clear();
  Mode mode() const { return mode_; }

 private:
  Mode mode_;
  bool shown_ = false;
};

}  // namespace sd::cli
