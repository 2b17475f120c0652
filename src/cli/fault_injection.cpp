#include "cli/fault_injection.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdlib>

namespace sd::cli {

std::int64_t kill_at_checkpoint() {
  static const std::int64_t at = [] {
    const char* text = std::getenv("SWARMDESIGN_KILL_AT_CHECKPOINT");
    return text ? std::strtoll(text, nullptr, 10) : 0;  // not a number: 0, no kill
  }();
  return at;
}

void kill_if_checkpoint(std::int64_t step) {
  if (kill_at_checkpoint() > 0 && step == kill_at_checkpoint()) ::kill(::getpid(), SIGKILL);
}

}  // namespace sd::cli
