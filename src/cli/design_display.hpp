#pragma once
// What a running design shows on the command line (a DesignObserver drawing a ProgressLine)
// and the final report as text; the JSON report is app::design_report_document.
#include <cstdint>

#include "app/design_job.hpp"
#include "cli/progress_line.hpp"

namespace sd::cli {

class DesignDisplay final : public app::DesignObserver {
 public:
  /// `maximise`: costs are shown as the mission's scores (-cost).
  DesignDisplay(ProgressLine::Mode mode, bool maximise);
  ~DesignDisplay() override { finish(); }

  void progress(const design::Progress& p) override;
  /// Where the tests' fault injection kills (cli/fault_injection.hpp).
  void checkpoint(std::int64_t step) override;
  /// Removes the live line (terminal) or logs the last race step (log) before the report.
  void finish();

 private:
  std::string line(const design::Progress& p) const;

  ProgressLine line_;
  bool maximise_;
  design::Progress last_{};
  bool have_last_ = false;
};

/// Text for people: how it ended, the best control software state by state, its string.
void print_design_report(const app::DesignReport& report);

}  // namespace sd::cli
