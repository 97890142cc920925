#include "tools/cli/progress.h"

#include <unistd.h>

#include <cstdio>

#include "tools/cli/interrupt.h"

namespace scallop {

bool ProgressBar::enabled() {
  return isatty(STDERR_FILENO) == 1;
}

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), lastDraw_(start_) {
  beginInterruptPolling();  // update() polls for Ctrl-C (tools/cli/interrupt.h)
}

ProgressBar::~ProgressBar() {
  finish();
  endInterruptPolling();
}

void ProgressBar::update(int64_t done, int64_t total) {
  throwIfInterrupted();  // Ctrl-C: every long loop reports progress (tools/cli/interrupt.h)
  if (!enabled() || total <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  const double frac = double(done) / double(total);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  for (int k = 0; k < kWidth; ++k) bar[k] = k < int(frac * kWidth) ? '#' : '.';
  bar[kWidth] = 0;
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.0f s elapsed, ETA %.0f s ", label_.c_str(), bar,
               100 * frac, elapsed, eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_ && !finished_) std::fputc('\n', stderr);
  finished_ = true;
}

}  // namespace scallop
