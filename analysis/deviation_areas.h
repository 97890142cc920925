// Areas of a design surface by its deviation: where the machined surface lies more than
// a scallop limit above the design, or deeper than the gouge tolerance below it
// (CONVENTIONS.md "Normal deviation on a design surface").
//
// The deviation is known at the vertices; across a facet it is taken as the linear
// interpolation of its three vertex values, and the area of the part of the facet where
// that linear function exceeds a threshold t is exact: with the values sorted
// f0 <= f1 <= f2 and A the facet's area, the part below t is the corner triangle at
// vertex 0 cut by the level line, A (t - f0)^2 / ((f1 - f0)(f2 - f0)) for f0 < t <= f1,
// and the part above it the corner triangle at vertex 2, A (f2 - t)^2 / ((f2 - f1)(f2 -
// f0)) for f1 <= t < f2 (the level line crosses the two edges from that vertex at the
// fractions (t - f0)/(f1 - f0), (t - f0)/(f2 - f0), and the corner triangle's area
// scales with their product).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "analysis/triangle_mesh.h"

namespace scallop {

// The area of triangle `corners` where the linear interpolation of `values` exceeds
// `threshold`, mm^2.
double triangleAreaAbove(const std::array<Vec3, 3>& corners, const std::array<double, 3>& values,
                         double threshold);

struct DeviationAreas {
  double measuredMm2 = 0;     // facets whose three vertices have a value
  double aboveLimitMm2 = 0;   // of those, deviation > scallop limit (0 without a limit)
  double gougedMm2 = 0;       // deviation < -gouge tolerance
  int64_t facetsLeftOut = 0;  // a vertex without a value (NaN)
};

// `deviation` one value per vertex of `mesh` (NaN: none); `scallopLimitMm` NaN: none.
DeviationAreas deviationAreas(const TriangleMesh& mesh, const std::vector<double>& deviation,
                              double scallopLimitMm, double gougeToleranceMm);

}  // namespace scallop
