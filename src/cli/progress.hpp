// A progress line on standard error for long runs, shown only when standard error is a
// terminal (never in logs or pipes), redrawn at most ten times a second.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>

#include "cslice/space.hpp"

namespace cslice::cli {

class ProgressLine {
 public:
  explicit ProgressLine(std::string command);
  ~ProgressLine();  // clears the line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // A report for SpaceOptions::progress (empty when standard error is not a terminal).
  ProgressReport report();

 private:
  void show(std::string_view stage, std::size_t done, std::size_t total);

  std::string command_;
  bool active_ = false;
  bool drawn_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace cslice::cli
