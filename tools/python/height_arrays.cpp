#include "tools/python/height_arrays.h"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>

#include "base/input_error.h"
#include "tools/io/height_export.h"
#include "tools/io/height_formats.h"

namespace scallop::python {

namespace py = pybind11;

// --- NumPy views of a ZMap ---------------------------------------------------------

py::array heightsView(const py::object& buffer) {
  ZMap& map = buffer.cast<HeightBuffer&>().map;
  const py::ssize_t nx = map.nx(), ny = map.ny();
  const py::ssize_t rowBytes = nx * py::ssize_t(sizeof(double));
  double* top = map.heights().data() + (ny - 1) * nx;  // the largest y: image row 0
  return py::array(py::dtype::of<double>(), {ny, nx}, {-rowBytes, py::ssize_t(sizeof(double))}, top,
                   buffer);
}

py::array heightsView(ZMap&& map) {
  if (map.nx() <= 0 || map.ny() <= 0) throw std::logic_error("an empty z-map has no view");
  return heightsView(py::cast(HeightBuffer{std::move(map)}));
}

ZMap zmapFromArray(const py::handle& heights, GridSpec grid, const char* field) {
  using Array = py::array_t<double, py::array::forcecast>;
  const Array a = Array::ensure(heights);
  if (!a) throw InputError(field, "expected an array of numbers (ny, nx)");
  if (a.ndim() != 2)
    throw InputError(field,
                     fmt::format("expected a 2-D array (ny, nx), got {} dimensions", a.ndim()));
  if (a.shape(0) < 1 || a.shape(1) < 1) throw InputError(field, "is empty");
  grid.nx = a.shape(1);
  grid.ny = a.shape(0);
  ZMap map(grid, 0.0);
  const auto h = a.unchecked<2>();
  for (int64_t r = 0; r < grid.ny; ++r)
    for (int64_t i = 0; i < grid.nx; ++i) map.at(i, grid.ny - 1 - r) = h(r, i);
  return map;
}

GridSpec gridFromPython(const py::handle& grid, const char* field) {
  if (py::isinstance<GridSpec>(grid)) return grid.cast<GridSpec>();
  if (!py::isinstance<py::dict>(grid) || !grid.contains("origin") || !grid.contains("spacing"))
    throw InputError(field,
                     "expected a scallop.Grid or a dict with \"origin\" [x, y] and "
                     "\"spacing\" (mm), like report[\"grid\"]");
  GridSpec g;
  try {
    const py::sequence origin = grid["origin"].cast<py::sequence>();
    if (py::len(origin) != 2) throw py::cast_error();
    g.originX = origin[0].cast<double>();
    g.originY = origin[1].cast<double>();
    g.spacing = grid["spacing"].cast<double>();
    if (grid.contains("nx")) g.nx = grid["nx"].cast<int64_t>();
    if (grid.contains("ny")) g.ny = grid["ny"].cast<int64_t>();
  } catch (const py::cast_error&) {
    throw InputError(field, "expected \"origin\" = [x, y] and \"spacing\" as numbers (mm)");
  }
  if (!std::isfinite(g.originX) || !std::isfinite(g.originY))
    throw InputError(std::string(field) + ".origin", "expected finite numbers (mm)");
  if (!(g.spacing > 0) || !std::isfinite(g.spacing))
    throw InputError(std::string(field) + ".spacing",
                     fmt::format("expected a length > 0 mm, got {:g}", g.spacing));
  return g;
}

namespace {

// Cell centres along x (increasing) or y (image row order: decreasing), mm.
py::array_t<double> centresX(const GridSpec& g) {
  py::array_t<double> x(g.nx);
  for (int64_t i = 0; i < g.nx; ++i) x.mutable_at(i) = g.cellCentreX(i);
  return x;
}

py::array_t<double> centresY(const GridSpec& g) {
  py::array_t<double> y(g.ny);
  for (int64_t r = 0; r < g.ny; ++r) y.mutable_at(r) = g.cellCentreY(g.ny - 1 - r);
  return y;
}

// --- read_heights / write_heights -------------------------------------------------

py::tuple readHeights(const std::string& path, bool withFrame) {
  ZMap map;
  std::string frame;
  {
    py::gil_scoped_release release;
    map = readHeightFile(path, &frame);
  }
  const GridSpec grid = map.grid();
  if (withFrame) return py::make_tuple(heightsView(std::move(map)), grid, frame);
  return py::make_tuple(heightsView(std::move(map)), grid);
}

void writeHeights(const std::string& path, const py::handle& heights, const py::handle& grid,
                  const std::string& title, const std::string& frame) {
  const GridSpec g = gridFromPython(grid, "grid");
  const ZMap map = zmapFromArray(heights, g, "heights");
  if ((g.nx > 0 && g.nx != map.nx()) || (g.ny > 0 && g.ny != map.ny()))
    throw InputError("heights", fmt::format("has the shape ({}, {}), but the grid is ny = {} by "
                                            "nx = {} cells",
                                            map.ny(), map.nx(), g.ny, g.nx));
  const HeightFormat& format = heightFormatOf(path, false);
  py::gil_scoped_release release;
  format.write(map, path, title, frame);
}

}  // namespace

void bindHeightArrays(py::module_& m) {
  py::class_<HeightBuffer>(m, "HeightBuffer",
                           "The C++ z-map that owns a height array's memory: the base object "
                           "of\nResult.heights and of read_heights()'s array. Stored with row "
                           "0 at the\nsmallest y; the arrays view it with row 0 at the largest "
                           "y.")
      .def_property_readonly(
          "address",
          [](const HeightBuffer& b) { return reinterpret_cast<uintptr_t>(b.map.heights().data()); },
          "Address of the first stored height (cell (0, 0), the smallest y).")
      .def_property_readonly(
          "nbytes", [](const HeightBuffer& b) { return b.map.heights().size() * sizeof(double); },
          "Bytes of heights held (8 per cell).")
      .def_property_readonly(
          "grid", [](const HeightBuffer& b) { return b.map.grid(); }, "The map's Grid.");

  py::class_<GridSpec>(m, "Grid",
                       "A z-map grid (CONVENTIONS.md): cell (i, j) is the square of side "
                       "`spacing`\nwhose centre is (origin[0] + (i + 1/2) spacing, origin[1] + "
                       "(j + 1/2) spacing),\nj counting up from the smallest y. In a height "
                       "array, column i is x and\nrow r is j = ny - 1 - r (row 0 = largest y). "
                       "Lengths in mm.")
      .def(py::init([](std::pair<double, double> origin, double spacing, int64_t nx, int64_t ny) {
             GridSpec g;
             g.originX = origin.first;
             g.originY = origin.second;
             g.spacing = spacing;
             g.nx = nx;
             g.ny = ny;
             if (!(spacing > 0) || !std::isfinite(spacing))
               throw InputError("spacing",
                                fmt::format("expected a length > 0 mm, got {:g}", spacing));
             if (nx < 1 || ny < 1)
               throw InputError("nx, ny", fmt::format("expected at least 1 cell each, got "
                                                      "{} x {}",
                                                      nx, ny));
             return g;
           }),
           py::arg("origin"), py::arg("spacing"), py::arg("nx"), py::arg("ny"),
           "Grid(origin=(x, y), spacing, nx, ny): origin is the minimum corner, mm.")
      .def_property_readonly(
          "origin", [](const GridSpec& g) { return py::make_tuple(g.originX, g.originY); },
          "(x, y) of the grid's minimum corner, mm.")
      .def_readonly("spacing", &GridSpec::spacing, "Cell side, mm.")
      .def_readonly("nx", &GridSpec::nx, "Cells along x (array columns).")
      .def_readonly("ny", &GridSpec::ny, "Cells along y (array rows).")
      .def_property_readonly("x", &centresX,
                             "Cell-centre x of every array column, mm (increasing).")
      .def_property_readonly("y", &centresY,
                             "Cell-centre y of every array row, mm (row 0 = largest y).")
      .def_property_readonly(
          "extent",
          [](const GridSpec& g) {
            return py::make_tuple(g.originX, g.originX + double(g.nx) * g.spacing, g.originY,
                                  g.originY + double(g.ny) * g.spacing);
          },
          "(x0, x1, y0, y1), mm: Matplotlib's imshow(heights, extent=grid.extent).")
      .def(
          "__eq__",
          [](const GridSpec& a, const GridSpec& b) {
            return a.originX == b.originX && a.originY == b.originY && a.spacing == b.spacing &&
                   a.nx == b.nx && a.ny == b.ny;
          },
          py::is_operator())
      .def("__repr__", [](const GridSpec& g) {
        return fmt::format("Grid(origin=({}, {}), spacing={}, nx={}, ny={})", g.originX, g.originY,
                           g.spacing, g.nx, g.ny);
      });

  m.def("read_heights", &readHeights, py::arg("path"), py::arg("with_frame") = false,
        "read_heights(path, with_frame=False) -> (heights, grid) or (heights, grid, frame)\n\n"
        "Reads a height map by the extension: .gsf (Gwyddion Simple Field) or .exr as\n"
        "scallop writes them, or .x3p (ISO 25178-72, float64 or float32 points).\n"
        "With with_frame, also the frame the heights are in (a job's grid.frame as the\n"
        "file names it; '' for a map seen from above), for write_heights(frame=...).\n"
        "heights is float64 (ny, nx), mm, row 0 = the largest y (a view of the map read,\n"
        "whose base is a HeightBuffer); grid is its Grid. GSF and EXR hold float32, so\n"
        "their heights are float32 values. Raises InputError naming the file for a\n"
        "missing, unreadable or inconsistent file.");
  m.def("write_heights", &writeHeights, py::arg("path"), py::arg("heights"), py::arg("grid"),
        py::arg("title") = "scallop heights", py::arg("frame") = "",
        "write_heights(path, heights, grid, title='scallop heights', frame='')\n\n"
        "Writes a height map (float64-convertible (ny, nx), mm, row 0 = the largest y) on\n"
        "grid (a Grid, or a dict with \"origin\" and \"spacing\" like report[\"grid\"]) in\n"
        "the format the extension names: .gsf (Gwyddion Simple Field, float32 metres),\n"
        ".exr (float32 channel Z, mm), .x3p (ISO 25178-72, float64 metres), .png/.tif\n"
        "(16-bit grey levels, see docs/formats.md). frame: the frame the heights are in\n"
        "(read_heights(..., with_frame=True)), kept in the file. The file appears only\n"
        "when complete.\n"
        "Raises InputError naming the field or the file.");
}

}  // namespace scallop::python
