// simulate(): a job run in memory (tools/run/simulation_run.h computeSimulation, the
// code `scallop simulate` runs) returning a Result with a NumPy view of the heights,
// the grid and report.json's document. Nothing is written.
//
// The computation runs with the GIL released. The caster's progress callback (called
// serialised from TBB's threads after every tile of cells) takes the GIL at most every
// 20 ms: on the Python main thread, which takes part in the parallel loop, it runs
// PyErr_CheckSignals, so Ctrl-C raises KeyboardInterrupt there; and it calls the user's
// progress(done, total), at most every 50 ms and once at the end. An exception from
// either unwinds the run (TBB cancels the other tiles) and is raised in the caller
// (tools/python/python_progress.h, which bench() uses too).
#pragma once

#include <pybind11/pybind11.h>

namespace scallop::python {

void bindSimulate(pybind11::module_& m);

}  // namespace scallop::python
