#include "tools/python/run_bindings.h"

#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "tools/python/json_convert.h"
#include "tools/python/python_progress.h"
#include "tools/run/bench_run.h"
#include "tools/run/gouge_run.h"
#include "tools/run/validation_run.h"

namespace scallop::python {

namespace py = pybind11;

namespace {

// The runs name the CLI's options ("--grid-spacing"); Python's keywords are the same
// words with underscores ("grid_spacing"), but for --case, which is cases=.
template <class Run>
auto namingKeywords(Run&& run) {
  try {
    return run();
  } catch (const InputError& e) {
    const std::string& where = e.where();
    if (where.rfind("--", 0) != 0) throw;
    std::string keyword = where == "--case" ? "cases" : where.substr(2);
    for (char& c : keyword)
      if (c == '-') c = '_';
    throw InputError(keyword, e.reason());
  }
}

int threadCount(std::optional<int> threads) {
  if (threads && *threads < 1)
    throw InputError("threads", "expected a number of threads >= 1 (None: all cores), got " +
                                    std::to_string(*threads));
  return threads.value_or(0);
}

std::string pathOrEmpty(const py::object& path) {
  if (path.is_none()) return {};
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

py::object gouge(const py::object& surface, double radius, double length, double sliceSpacing,
                 const std::string& feed, double ccStep, double ccPosition, double inclinationStep,
                 double inclinationMax, const std::string& inclinationAxis, bool bothWays,
                 double testLength, double tolerance, double mapTolerance, double gridSpacing,
                 bool map, const std::string& normals, const py::object& postures,
                 const py::object& output, std::optional<int> threads) {
  GougeSettings s;
  s.surface = pathOrEmpty(surface);
  s.radius = radius;
  s.length = length;
  s.strategy.sliceSpacing = sliceSpacing;
  s.feed = feed;
  s.strategy.ccStep = ccStep;
  s.strategy.ccAxialPosition = ccPosition;
  s.strategy.inclinationStepDeg = inclinationStep;
  s.strategy.inclinationMaxDeg = inclinationMax;
  s.inclinationAxis = inclinationAxis;
  s.strategy.inclineBothWays = bothWays;
  s.strategy.vertexTestLength = testLength;
  s.strategy.gougeTolerance = tolerance;
  s.mapTolerance = mapTolerance;
  s.gridSpacing = gridSpacing;
  s.noMap = !map;
  s.normals = normals;
  s.posturesCsv = pathOrEmpty(postures);
  s.outDir = pathOrEmpty(output);
  s.threads = threadCount(threads);
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    std::unique_ptr<tbb::global_control> threadLimit;
    if (threads)
      threadLimit = std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, size_t(*threads));
    report = namingKeywords([&] { return runGouge(s); }).report;
  }
  return toPython(report);
}

py::object validate(const py::object& output) {
  ValidationSettings s;
  s.outDir = pathOrEmpty(output);
  nlohmann::json document;
  {
    py::gil_scoped_release release;
    document = runValidation(s).document;
  }
  return toPython(document);
}

py::object bench(std::optional<std::vector<std::string>> cases, bool quick,
                 std::optional<double> area, std::optional<double> stampWindow, bool stamp,
                 std::optional<int> threads, const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InputError("progress", "expected a callable progress(done, total) or None");
  if (area && !(*area > 0)) throw InputError("area", "expected a stock side > 0 mm or None");
  if (stampWindow && !(*stampWindow > 0))
    throw InputError("stamp_window", "expected a window side > 0 mm or None");
  BenchSettings s;
  s.cases = cases.value_or(std::vector<std::string>());
  s.quick = quick;
  s.area = area.value_or(0.0);
  s.stampWindow = stampWindow.value_or(0.0);
  s.stamp = stamp;
  s.threads = threadCount(threads);
  PythonProgress poller(progress);
  s.openStage = [&poller](const std::string&) -> CellProgress {
    return [&poller](int64_t done, int64_t total) { poller(done, total); };
  };
  nlohmann::json report;
  try {
    py::gil_scoped_release release;
    report = namingKeywords([&] { return runBench(s); }).report;
  } catch (const PythonCancel&) {
    poller.raise();
  }
  return toPython(report);
}

}  // namespace

void bindRuns(py::module_& m) {
  const GougeSettings g;
  const StrategyOptions& so = g.strategy;
  m.def("gouge", &gouge, py::arg("surface"), py::arg("radius"), py::arg("length"), py::kw_only(),
        py::arg("slice_spacing") = so.sliceSpacing, py::arg("feed") = g.feed,
        py::arg("cc_step") = so.ccStep, py::arg("cc_position") = so.ccAxialPosition,
        py::arg("inclination_step") = so.inclinationStepDeg,
        py::arg("inclination_max") = so.inclinationMaxDeg,
        py::arg("inclination_axis") = g.inclinationAxis, py::arg("both_ways") = so.inclineBothWays,
        py::arg("test_length") = so.vertexTestLength, py::arg("tolerance") = so.gougeTolerance,
        py::arg("map_tolerance") = g.mapTolerance, py::arg("grid_spacing") = g.gridSpacing,
        py::arg("map") = true, py::arg("normals") = g.normals, py::arg("postures") = py::none(),
        py::arg("output") = py::none(), py::arg("threads") = py::none(),
        "gouge(surface, radius, length, *, slice_spacing=0, feed='x', cc_step=0,\n"
        "      cc_position=0, inclination_step=0.5, inclination_max=10,\n"
        "      inclination_axis='normal', both_ways=False, test_length=0,\n"
        "      tolerance=1e-6, map_tolerance=0.01, grid_spacing=0, map=True,\n"
        "      normals='up', postures=None, output=None, threads=None) -> dict\n\n"
        "Seed 004's peripheral-milling strategy with a flat cutter (radius R, flute\n"
        "length L, mm) on an STL surface, the exact check of every accepted posture and\n"
        "the gouge map: the report `scallop gouge --json` prints (see `scallop gouge\n"
        "--help` for each option; 0 means the option's default there). postures: a CSV\n"
        "file to write, one row per cc-point; output: a folder for report.json,\n"
        "gouge_map.png and gouge_depth.exr. Raises InputError naming the keyword.");
  m.def("validate", &validate, py::arg("output") = ValidationSettings().outDir,
        "validate(output='scallop-validation') -> dict\n\n"
        "The validation run: seed 000 Tables 2-5 and seed 001 Tables 1-4 with the\n"
        "simulated truth beside the printed values, written into the folder `output` as\n"
        "CSV tables and profiles/*.svg; returns the document `scallop validate --json`\n"
        "prints ({'output_dir', 'tables', 'pictures', 'units'}).");
  m.def("bench", &bench, py::arg("cases") = py::none(), py::kw_only(), py::arg("quick") = false,
        py::arg("area") = py::none(), py::arg("stamp_window") = py::none(), py::arg("stamp") = true,
        py::arg("threads") = py::none(), py::arg("progress") = py::none(),
        "bench(cases=None, *, quick=False, area=None, stamp_window=None, stamp=True,\n"
        "      threads=None, progress=None) -> dict\n\n"
        "The standard performance cases (a list of 'B1', 'B2', 'B3', 'B3c', 'B4', 'B5',\n"
        "'B9'; None: all but B9, a million moves), each run at 1 thread and at `threads` (None: "
        "2), and the stamping\n"
        "baseline (stamp=False skips it): the document `scallop bench --json` prints.\n"
        "quick: 10x coarser grids; area: a square stock of this side, mm; stamp_window:\n"
        "the baseline's window side, mm. progress(done, total) in cells is called for\n"
        "each run as simulate() calls it, and Ctrl-C stops the run.");
}

}  // namespace scallop::python
