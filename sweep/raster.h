// Raster tool paths with lead and tilt (CONVENTIONS.md "Raster generator",
// "Lead and tilt").
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "base/vec3.h"

namespace scallop {

struct RasterSpec {
  char direction = 'x';      // feed along 'x' or 'y'
  double stepOver = 1.0;     // L, mm between passes
  double depth = 0.5;        // mm from the stock top to the cutter's lowest point
  double leadDeg = 0;        // rho: axis rotated from +Z towards +f
  double tiltDeg = 0;        // tau: axis rotated from +Z towards +c = z x f
  bool zigzag = false;       // alternate the feed direction between passes
  double segmentLength = 0;  // > 0: cut each pass into moves of at most this length, mm
};

// The tool axis for feed f and cross-feed c = z x f: a = normalize(tan(rho) f +
// tan(tau) c + z), so the axis projected on the (f, z) plane makes rho with +Z and on
// the (c, z) plane makes tau. With only one angle this is the plain rotation.
Vec3 leadTiltAxis(const Vec3& feed, double leadDeg, double tiltDeg);

// Validates `spec` (InputError naming "path.raster.<field>") and builds the path.
ToolPath makeRaster(const Cutter& cutter, const Box3& stock, const RasterSpec& spec);

}  // namespace scallop
