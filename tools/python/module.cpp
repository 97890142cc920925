// The Python module `scallop`: the simulator for scripts and notebooks.
// simulate() runs a job in memory and returns NumPy heights; interval() and stats() are
// `scallop interval --json` and `scallop stats --json`'s surface_stats; read_heights()
// and write_heights() exchange height files; gouge(), validate() and bench() are those
// commands' runs and documents. Every function is the code the CLI runs
// (tools/run, tools/io), so a script and the command line agree to the bit. A tool
// like tools/cli: it sits on scallop_run and nothing below includes it.
#include <pybind11/pybind11.h>

#include "base/input_error.h"
#include "base/version.h"
#include "tools/python/analysis_bindings.h"
#include "tools/python/height_arrays.h"
#include "tools/python/run_bindings.h"
#include "tools/python/simulate_binding.h"

namespace py = pybind11;

PYBIND11_MODULE(scallop, m) {
  m.doc() =
      "scallop: exact machined-surface topography of milling tool paths.\n\n"
      "Sweeps milling cutters of any convex profile (ball, flat, bull, tapered, cone,\n"
      "barrel, APT CUTTER) along tool paths and computes on a\n"
      "z-map grid the exact lowest point of the swept solids, in double precision.\n"
      "Lengths in mm, angles in degrees (docs/CONVENTIONS.md).\n\n"
      "  simulate(job) -> Result      heights (NumPy view, row 0 = largest y), grid, report\n"
      "  interval(tool=..., ...)      path intervals of the seeds vs the simulated truth\n"
      "  stats(heights, spacing)      ISO 25178-2 Sa, Sq, Ssk, Sku, Sp, Sv, Sz\n"
      "  read_heights(path)           .gsf / .exr / .x3p -> (heights, grid)\n"
      "  write_heights(path, h, grid) .gsf / .exr / .x3p / .png / .tif\n"
      "  gouge(surface, radius, length, ...)  seed 004's strategy and gouge check (report)\n"
      "  validate(output)             the seed tables vs the simulated truth (CSV + SVG)\n"
      "  bench(cases, quick=...)      the standard performance cases (bench --json)\n"
      "  InputError                   bad input (a ValueError); the message names the field\n\n"
      "Example:\n"
      "  import scallop\n"
      "  r = scallop.simulate({'tool': {'type': 'ball', 'radius': 3},\n"
      "                        'stock': {'min': [0, 0, -5], 'max': [10, 10, 0]},\n"
      "                        'grid': {'spacing': 0.05},\n"
      "                        'path': {'raster': {'direction': 'x', 'step_over': 1,\n"
      "                                            'depth': 0.5}}})\n"
      "  print(r.heights.shape, r.report['measurements']['max_scallop_height'])";
  m.attr("__version__") = scallop::kScallopVersion;
  py::register_exception<scallop::InputError>(m, "InputError", PyExc_ValueError).doc() =
      "Bad input: the message names the file, line, field or keyword and what was "
      "expected\n(the CLI's exit status 1). A subclass of ValueError.";
  scallop::python::bindHeightArrays(m);
  scallop::python::bindSimulate(m);
  scallop::python::bindAnalysis(m);
  scallop::python::bindRuns(m);
}
