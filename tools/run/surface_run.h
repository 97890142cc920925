// `scallop surface`'s work: a faceted analytic surface (analysis/analytic_surfaces.h, the
// stand-ins for seed 004's unpublished test models) written as STL, and its summary.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/analytic_surfaces.h"

namespace scallop {

struct SurfaceSettings {
  SurfaceSpec spec;
  std::string shape = "dome";  // parsed into spec.shape (InputError naming --shape)
  std::string output;          // FILE.stl (InputError naming -o when empty)
  bool ascii = false;          // ASCII STL instead of binary
};

// Writes the surface and returns its summary: output, format, shape, size_mm, height_mm,
// triangles, vertices, z_range_mm (and trough_radius_mm for a trough).
nlohmann::json writeAnalyticSurface(SurfaceSettings settings);

}  // namespace scallop
