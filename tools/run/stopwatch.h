// secondsSince: the wall-clock seconds that report.json and the benchmark give, on the
// monotonic clock (a change of the system time cannot make a timing negative).
#pragma once

#include <chrono>

namespace scallop {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace scallop
