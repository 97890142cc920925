#include "tools/python/python_progress.h"

#include <stdexcept>
#include <utility>

namespace scallop::python {

namespace py = pybind11;

PythonProgress::PythonProgress(py::object callback)
    : callback_(std::move(callback)), mainThread_(std::this_thread::get_id()) {}

void PythonProgress::operator()(int64_t done, int64_t total) {
  // Tiles that other threads finish while the cancellation spreads call in vain.
  if (error_) throw PythonCancel();
  const Clock::time_point now = Clock::now();
  const bool poll = std::this_thread::get_id() == mainThread_ && now - lastPoll_ >= kPollEvery;
  const bool report = !callback_.is_none() && (done == total || now - lastReport_ >= kReportEvery);
  if (!poll && !report) return;
  py::gil_scoped_acquire gil;
  if (poll) {
    lastPoll_ = now;
    if (PyErr_CheckSignals() != 0) cancelWithPythonError();
  }
  if (report) {
    lastReport_ = now;
    try {
      callback_(done, total);
    } catch (py::error_already_set& e) {
      error_ = std::move(e);
      throw PythonCancel();
    }
  }
}

void PythonProgress::raise() {
  if (error_) throw *error_;
  throw std::logic_error("a cancelled run without a Python error");
}

void PythonProgress::cancelWithPythonError() {
  error_.emplace();  // fetches the error that PyErr_CheckSignals set
  throw PythonCancel();
}

}  // namespace scallop::python
