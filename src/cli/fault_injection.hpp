#pragma once
// Fault injection for the kill-and-resume tests: with SWARMDESIGN_KILL_AT_CHECKPOINT=N in its
// environment, a design (checkpoint N) or an evolution (generation N) SIGKILLs its own process
// right after that state is durable, so a test kills at exactly the step it means to, on a
// machine of any speed. Unset, nothing happens.
#include <cstdint>

namespace sd::cli {

/// N, or 0 when the variable is unset.
std::int64_t kill_at_checkpoint();
/// SIGKILLs this process when `step` is the N asked for.
void kill_if_checkpoint(std::int64_t step);

}  // namespace sd::cli
