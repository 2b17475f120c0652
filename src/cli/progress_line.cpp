#include "cli/progress_line.hpp"

#include <unistd.h>

#include <cstdio>
#include <ctime>

namespace sd::cli {

ProgressLine::Mode ProgressLine::terminal_if(bool wanted) {
  return wanted && isatty(STDERR_FILENO) ? Mode::Terminal : Mode::Off;
}

void ProgressLine::show(const std::string& text) {
  if (mode_ != Mode::Terminal) return;
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  shown_ = true;
}

void ProgressLine::log(const std::string& text) {
  if (mode_ != Mode::Log) return;
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::tm local{};
  localtime_r(&now, &local);  // not localtime: a design's jobs log from several threads
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", &local);
  std::fprintf(stderr, "%s  %s\n", stamp, text.c_str());
  std::fflush(stderr);
}

void ProgressLine::clear() {
  if (mode_ == Mode::Terminal && shown_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
  }
}

}  // namespace sd::cli
