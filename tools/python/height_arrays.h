// Height maps in Python: a ZMap held by a HeightBuffer and shown as a NumPy view, the
// Grid class, and heights.gsf / .exr / .x3p read and written through tools/io.
//
// NumPy arrays are (ny, nx) float64 with row 0 = the largest y (image order, as every
// height image of CONVENTIONS.md). A ZMap stores row j = 0 at the smallest y, so the
// view starts at its last row with a negative row stride: no copy. The view's base is
// the HeightBuffer that owns the ZMap, which lives as long as any view of it does.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "raycast/zmap.h"

namespace scallop::python {

// The owner of a ZMap's heights behind NumPy views (scallop.HeightBuffer).
struct HeightBuffer {
  ZMap map;
};

// A view of `buffer` (a HeightBuffer object): shape (ny, nx), row 0 = largest y.
pybind11::array heightsView(const pybind11::object& buffer);

// A view of `map`, moved into a new HeightBuffer.
pybind11::array heightsView(ZMap&& map);

// A copy of `heights` (2-D, any real dtype, row 0 = largest y) as a ZMap on `grid`
// (whose nx and ny are set from the shape). InputError naming `field` for another
// number of dimensions or an empty array.
ZMap zmapFromArray(const pybind11::handle& heights, GridSpec grid, const char* field);

// A Grid object, or a mapping with "origin" (x, y) and "spacing" like report.json's
// "grid", as a GridSpec; nx and ny are taken from it when present. InputError naming
// `field` otherwise.
GridSpec gridFromPython(const pybind11::handle& grid, const char* field);

// Adds HeightBuffer, Grid, read_heights and write_heights to the module.
void bindHeightArrays(pybind11::module_& m);

}  // namespace scallop::python
