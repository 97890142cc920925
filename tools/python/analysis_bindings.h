// interval() and stats(): the Python module's face of `scallop interval --json`
// (tools/run/interval_comparison.h) and of `scallop stats --json`'s "surface_stats"
// (tools/run/stats_document.h), computed by the same code as the commands.
#pragma once

#include <pybind11/pybind11.h>

namespace scallop::python {

void bindAnalysis(pybind11::module_& m);

}  // namespace scallop::python
