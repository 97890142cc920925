#include "tools/python/simulate_binding.h"

#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <memory>
#include <optional>
#include <string>

#include "base/input_error.h"
#include "tools/io/job.h"
#include "tools/python/height_arrays.h"
#include "tools/python/json_convert.h"
#include "tools/python/python_progress.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop::python {

namespace py = pybind11;

namespace {

// The result of simulate().
struct Result {
  py::object heights;  // float64 (ny, nx) view of a HeightBuffer
  GridSpec grid;
  py::object report;  // dict
};

// The job's JSON text and its source name: a dict, or a path to a job file.
struct JobInput {
  std::string text, source, file;
};

JobInput jobInput(const py::handle& job) {
  JobInput in;
  if (py::isinstance<py::dict>(job)) {
    in.text = fromPython(job, "").dump();
    in.source = "job";
    return in;
  }
  const py::module_ os = py::module_::import("os");
  if (py::isinstance<py::str>(job) || py::isinstance(job, os.attr("PathLike"))) {
    in.file = os.attr("fspath")(job).cast<std::string>();
    return in;
  }
  throw InputError("job", "expected a dict (the job file's JSON) or the path of a job file");
}

Result simulatePython(const py::object& job, std::optional<int> threads, const py::object& progress,
                      const std::string& method, bool verbose) {
  if (threads && *threads < 1)
    throw InputError("threads", "expected a number of threads >= 1 (None: all cores), got " +
                                    std::to_string(*threads));
  if (method != "exact" && method != "stamp")
    throw InputError("method", "expected \"exact\" or \"stamp\", got \"" + method + "\"");
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InputError("progress", "expected a callable progress(done, total) or None");
  const JobInput input = jobInput(job);

  PythonProgress poller(progress);
  RunSettings settings;
  settings.threads = threads.value_or(0);
  settings.quiet = !verbose;
  settings.method = method;
  settings.progress = [&poller](int64_t done, int64_t total) { poller(done, total); };

  ComputedSimulation run;
  try {
    py::gil_scoped_release release;
    std::unique_ptr<tbb::global_control> threadLimit;
    if (threads)
      threadLimit = std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, size_t(*threads));
    const Job loaded =
        input.file.empty() ? loadJob(input.text, input.source) : loadJobFile(input.file);
    run = computeSimulation(loaded, settings);
  } catch (const PythonCancel&) {
    poller.raise();
  }
  Result result;
  result.grid = run.map.grid();
  result.report = toPython(run.report);
  result.heights = heightsView(std::move(run.map));
  return result;
}

}  // namespace

void bindSimulate(py::module_& m) {
  py::class_<Result>(m, "Result",
                     "What simulate() returns: heights (a view of the computed z-map), grid "
                     "and\nreport.")
      .def_readonly("heights", &Result::heights,
                    "float64 array (ny, nx) of absolute heights, mm; row 0 = the largest y, "
                    "column 0\n= the smallest x. A view of the computed map (heights.base is "
                    "its HeightBuffer),\nnot a copy.")
      .def_readonly("grid", &Result::grid, "The Grid: origin, spacing, nx, ny.")
      .def_readonly("report", &Result::report,
                    "report.json's document as a dict (what `scallop simulate --json` "
                    "prints), with\n\"outputs\" empty since nothing is written.")
      .def("__repr__", [](const Result& r) {
        return "<scallop.Result " + std::to_string(r.grid.nx) + " x " + std::to_string(r.grid.ny) +
               " cells>";
      });

  m.def("simulate", &simulatePython, py::arg("job"), py::arg("threads") = py::none(),
        py::arg("progress") = py::none(), py::kw_only(), py::arg("method") = "exact",
        py::arg("verbose") = false,
        "simulate(job, threads=None, progress=None, *, method='exact', verbose=False)\n"
        "    -> Result\n\n"
        "Computes a job's exact heights in memory, as `scallop simulate` does, and writes\n"
        "nothing. job is a dict with the job file's keys (docs/CONVENTIONS.md: tool,\n"
        "stock, grid, path, ...; relative file names are taken from the current folder)\n"
        "or the path of a job file (relative names from its folder).\n"
        "threads: worker threads (None: all cores); the heights do not depend on it.\n"
        "progress: None or a callable progress(done, total) in cells, called at most\n"
        "every 0.05 s and once at the end; an exception it raises stops the run.\n"
        "method: 'exact' or 'stamp' (the classical z-map baseline).\n"
        "verbose: print the CLI's summary lines and path-file warnings on stderr.\n\n"
        "The GIL is released while it computes, and Ctrl-C (KeyboardInterrupt) stops it\n"
        "within a tile of cells. A bad job raises InputError naming the field, e.g.\n"
        "\"job: grid.spacing: ...\".\n\n"
        "Result.heights is float64 (ny, nx), mm, row 0 = the largest y, a view of the\n"
        "map; Result.grid its Grid; Result.report the report.json dict.");
}

}  // namespace scallop::python
