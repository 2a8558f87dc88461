#include "cli/progress.hpp"

#include <unistd.h>
#include <cstdio>

namespace cslice::cli {

namespace {
constexpr auto kRedrawEvery = std::chrono::milliseconds(100);
}

ProgressLine::ProgressLine(std::string command)
    : command_(std::move(command)), active_(isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() {
  if (drawn_) std::fprintf(stderr, "\r\033[K");
}

ProgressReport ProgressLine::report() {
  if (!active_) return {};
  return [this](std::string_view stage, std::size_t done, std::size_t total) {
    show(stage, done, total);
  };
}

void ProgressLine::show(std::string_view stage, std::size_t done, std::size_t total) {
  const std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  // Stage starts and ends always show; steps in between at the redraw rate.
  if (done != 0 && done != total && now - last_ < kRedrawEvery) return;
  last_ = now;
  drawn_ = true;
  std::fprintf(stderr, "\r\033[K%s: %.*s %zu/%zu", command_.c_str(), int(stage.size()),
               stage.data(), done, total);
  std::fflush(stderr);
}

}  // namespace cslice::cli
