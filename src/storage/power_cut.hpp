#pragma once
// Fault injection for the crash-loop benchmark (bench/crash_loop.py) and the kill-and-resume
// tests: a power cut in the middle of a design database's write. With SWARMDESIGN_POWER_CUT=N:K
// in its environment, the process writes only the first half of the K-th file write of its N-th
// design-database write (DesignStore::create counts as one, each checkpoint's append as one)
// and SIGKILLs itself there: a torn write inside SQLite's commit. When that write makes fewer
// than K file writes, the kill comes right after it is complete, before the caller hears of it.
// Unset (always, outside the benchmark and tests), no VFS is installed and nothing is counted.
#include <cstdint>

namespace sd::storage {

/// Installs the counting SQLite VFS as the default once, when the variable is set; called
/// before every connection opens, so the design's database goes through it.
void install_power_cut_if_asked();

/// Around one design-database write: arms the cut on this thread when it is the N-th.
class PowerCutWindow {
 public:
  PowerCutWindow();
  ~PowerCutWindow();
  PowerCutWindow(const PowerCutWindow&) = delete;
  PowerCutWindow& operator=(const PowerCutWindow&) = delete;
  /// The write is complete: when armed, the cut comes now.
  void committed();

 private:
  bool armed_ = false;
};

}  // namespace sd::storage
