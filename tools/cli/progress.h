// ProgressBar: a one-line progress bar with ETA on stderr, shown only on a terminal
// (CONVENTIONS.md: progress goes to stderr, and only on a TTY).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace scallop {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  // Safe to call often: redraws at most ~10 times a second.
  void update(int64_t done, int64_t total);
  void finish();
  static bool enabled();

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  bool drawn_ = false, finished_ = false;
};

}  // namespace scallop
