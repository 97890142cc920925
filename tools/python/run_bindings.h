// gouge(), validate() and bench(): the runs of `scallop gouge`, `scallop validate` and
// `scallop bench` (tools/run/gouge_run.h, validation_run.h, bench_run.h) returning the
// document their --json prints, as a dict. Each computes with the GIL released; bench()
// polls Ctrl-C and calls progress(done, total) as simulate() does
// (tools/python/python_progress.h). Errors name the keyword, not the CLI's option.
#pragma once

#include <pybind11/pybind11.h>

namespace scallop::python {

void bindRuns(pybind11::module_& m);

}  // namespace scallop::python
