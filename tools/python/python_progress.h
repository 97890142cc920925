// PythonProgress: the progress callback of a run computed with the GIL released
// (simulate(), bench()). Called serialised from TBB's threads after every tile of
// cells, it takes the GIL at most every 20 ms: on the Python main thread, which takes
// part in the parallel loop, it runs PyErr_CheckSignals, so Ctrl-C raises
// KeyboardInterrupt there; and it calls the user's progress(done, total), at most every
// 50 ms and once at the end. Either error throws PythonCancel through the C++ run (TBB
// cancels the other tiles); the caller catches it with the GIL held and calls raise().
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>

namespace scallop::python {

// Thrown through the C++ run to stop it; the Python error it stands for is raised after.
struct PythonCancel {};

class PythonProgress {
 public:
  // With the GIL held; `callback` is None or a callable progress(done, total).
  explicit PythonProgress(pybind11::object callback);

  // Any thread, serialised by the caster, without the GIL.
  void operator()(int64_t done, int64_t total);

  // With the GIL held, after a PythonCancel: raises the Python error it stands for.
  [[noreturn]] void raise();

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kPollEvery{20}, kReportEvery{50};

  [[noreturn]] void cancelWithPythonError();

  pybind11::object callback_;
  std::thread::id mainThread_;
  Clock::time_point lastPoll_{}, lastReport_{};
  std::optional<pybind11::error_already_set> error_;
};

}  // namespace scallop::python
