#pragma once
// What every target does when it meets a finding that is not a sanitizer report: say what
// broke on one line and abort, so libFuzzer saves the input as a crash-* file. With
// SD_FUZZ_PAUSE set it waits an hour first, for a debugger to attach (gdb -p) and look at the
// process as it was (the HTTP target's threads, sockets and server state).
#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <string>

namespace sd::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
  if (std::getenv("SD_FUZZ_PAUSE")) {
    std::fflush(stderr);
    ::sleep(3600);
  }
  std::abort();
}

}  // namespace sd::fuzz
