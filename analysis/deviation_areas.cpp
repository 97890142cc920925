// Areas of a design by its deviation: see deviation_areas.h for the derivation.
#include "analysis/deviation_areas.h"

#include <algorithm>
#include <cmath>

namespace scallop {

double triangleAreaAbove(const std::array<Vec3, 3>& c, const std::array<double, 3>& values,
                         double t) {
  const double area = 0.5 * length(cross(c[1] - c[0], c[2] - c[0]));
  std::array<double, 3> f = values;
  std::sort(f.begin(), f.end());
  if (t >= f[2]) return 0;
  if (t < f[0]) return area;
  if (t <= f[1])  // f0 <= t <= f1, f0 < f2: below t, the corner triangle at vertex 0
    return f[1] > f[0] ? area * (1 - (t - f[0]) * (t - f[0]) / ((f[1] - f[0]) * (f[2] - f[0])))
                       : area;
  // f1 < t < f2: above t, the corner triangle at vertex 2.
  return area * (f[2] - t) * (f[2] - t) / ((f[2] - f[1]) * (f[2] - f[0]));
}

DeviationAreas deviationAreas(const TriangleMesh& mesh, const std::vector<double>& w, double limit,
                              double tolerance) {
  DeviationAreas a;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& ids = mesh.triangles[t];
    const std::array<double, 3> v = {w[ids[0]], w[ids[1]], w[ids[2]]};
    if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2])) {
      ++a.facetsLeftOut;
      continue;
    }
    const std::array<Vec3, 3> c = mesh.corners(t);
    const double area = triangleAreaAbove(c, v, -HUGE_VAL);
    a.measuredMm2 += area;
    if (!std::isnan(limit)) a.aboveLimitMm2 += triangleAreaAbove(c, v, limit);
    a.gougedMm2 += area - triangleAreaAbove(c, v, -tolerance);
  }
  return a;
}

}  // namespace scallop
