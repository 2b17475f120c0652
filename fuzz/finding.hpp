#pragma once
// What every target does when it meets a finding that is not a sanitizer report: say what
// broke on one line and abort, so libFuzzer saves the input as a crash-* file.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace sd::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
  std::abort();
}

}  // namespace sd::fuzz
