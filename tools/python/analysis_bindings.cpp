#include "tools/python/analysis_bindings.h"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "base/input_error.h"
#include "tools/python/height_arrays.h"
#include "tools/python/json_convert.h"
#include "tools/run/interval_comparison.h"
#include "tools/run/stats_document.h"

namespace scallop::python {

namespace py = pybind11;

namespace {

// Errors name the keywords, as the CLI's name its options.
constexpr IntervalFieldNames kKeywords{"tool", "radius", "corner_radius",
                                       "lead", "tilt",   "scallop"};

py::object interval(const std::string& tool, double radius, double scallop,
                    std::optional<double> cornerRadius, double lead, double tilt) {
  IntervalRequest request;
  request.tool = tool;
  request.radiusMm = radius;
  request.cornerGiven = cornerRadius.has_value();
  request.cornerRadiusMm = cornerRadius.value_or(0.0);
  request.leadDeg = lead;
  request.tiltDeg = tilt;
  request.scallopMm = scallop;
  nlohmann::json doc;
  {
    py::gil_scoped_release release;
    doc = toJson(compareIntervals(request, kKeywords));
  }
  return toPython(doc);
}

py::object stats(const py::handle& heights, const py::handle& spacing,
                 std::optional<std::vector<double>> region, const std::string& level,
                 std::optional<std::pair<double, double>> origin) {
  GridSpec grid;
  if (py::isinstance<GridSpec>(spacing) || py::isinstance<py::dict>(spacing)) {
    if (origin) throw InputError("origin", "is given by the grid; leave it out");
    grid = gridFromPython(spacing, "spacing");
  } else {
    try {
      grid.spacing = spacing.cast<double>();
    } catch (const py::cast_error&) {
      throw InputError("spacing", "expected a cell side in mm, a Grid or a grid dict");
    }
    if (!(grid.spacing > 0) || !std::isfinite(grid.spacing))
      throw InputError("spacing", fmt::format("expected a length > 0 mm, got {:g}", grid.spacing));
    if (origin) grid.originX = origin->first, grid.originY = origin->second;
  }
  const int64_t gridNx = grid.nx, gridNy = grid.ny;
  const ZMap map = zmapFromArray(heights, grid, "heights");
  if ((gridNx > 0 && gridNx != map.nx()) || (gridNy > 0 && gridNy != map.ny()))
    throw InputError("heights", fmt::format("has the shape ({}, {}), but the grid is ny = {} by "
                                            "nx = {} cells",
                                            map.ny(), map.nx(), gridNy, gridNx));
  const Levelling levelling = parseLevelling(level, "level");
  const CellRegion cells =
      statsRegion(map.grid(), region.value_or(std::vector<double>()), "region");
  nlohmann::json doc;
  {
    py::gil_scoped_release release;
    doc = surfaceStatsDocument(map, cells, levelling);
  }
  return toPython(doc["surface_stats"]);
}

}  // namespace

void bindAnalysis(py::module_& m) {
  m.def("interval", &interval, py::kw_only(), py::arg("tool"), py::arg("radius"),
        py::arg("scallop"), py::arg("corner_radius") = py::none(), py::arg("lead") = 0.0,
        py::arg("tilt") = 0.0,
        "interval(*, tool, radius, scallop, corner_radius=None, lead=0, tilt=0) -> dict\n\n"
        "Path interval (half step-over L/2, mm) for a scallop height h = `scallop` (mm) by\n"
        "every procedure of the seeds, each with the scallop two simulated passes 2 L/2\n"
        "apart really leave, and the simulated exact L/2: the document of\n"
        "`scallop interval --json`, number for number. tool is 'ball', 'bull' or 'flat';\n"
        "radius R and corner_radius r (bull only, 0 < r < R) in mm; lead (towards the\n"
        "feed) and tilt (towards the cross-feed) in degrees, |angle| < 90.\n"
        "Raises InputError naming the keyword, e.g. for an h the cutter cannot leave.\n\n"
        "Example: scallop.interval(tool='bull', radius=3, corner_radius=1, lead=5,\n"
        "                          scallop=0.05)['simulated_half_interval']");
  m.def("stats", &stats, py::arg("heights"), py::arg("spacing"), py::arg("region") = py::none(),
        py::arg("level") = "plane", py::arg("origin") = py::none(),
        "stats(heights, spacing, region=None, level='plane', origin=None) -> dict\n\n"
        "ISO 25178-2 height parameters (Sa, Sq, Ssk, Sku, Sp, Sv, Sz, mm) of a height map\n"
        "(ny, nx), row 0 = largest y: the \"surface_stats\" block of `scallop stats\n"
        "--json` (and of report.json), computed by the same code. spacing is the cell\n"
        "side in mm, or a Grid (Result.grid, read_heights' grid) or report['grid'], which\n"
        "also give the origin; otherwise origin = (x, y) of the minimum corner, default\n"
        "(0, 0). region = (x0, y0, x1, y1), mm: only the cells whose centres lie in it.\n"
        "level: 'plane' (least-squares plane) or 'none' (heights from the mean).\n"
        "Sku is the plain kurtosis (3 for a Gaussian surface).");
}

}  // namespace scallop::python
