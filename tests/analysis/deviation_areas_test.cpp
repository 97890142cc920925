// Areas of a design by its deviation (analysis/deviation_areas.h), against an independent
// computation: the triangle clipped by the half-plane where the interpolated value
// exceeds the threshold (Sutherland-Hodgman), measured by the shoelace formula in the
// triangle's own plane.
#include "analysis/deviation_areas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace scallop {
namespace {

// The clipped polygon's area: corners in the triangle's plane coordinates (s, t) of the
// edges from corner 0, the value linear in (s, t).
double clippedArea(const std::array<Vec3, 3>& c, const std::array<double, 3>& f, double t) {
  struct P {
    double s, t, f;
  };
  const std::vector<P> tri = {{0, 0, f[0]}, {1, 0, f[1]}, {0, 1, f[2]}};
  std::vector<P> out;
  for (size_t k = 0; k < 3; ++k) {
    const P& a = tri[k];
    const P& b = tri[(k + 1) % 3];
    const bool ina = a.f > t, inb = b.f > t;
    if (ina) out.push_back(a);
    if (ina != inb) {
      const double u = (t - a.f) / (b.f - a.f);
      out.push_back({a.s + u * (b.s - a.s), a.t + u * (b.t - a.t), t});
    }
  }
  double twice = 0;
  for (size_t k = 0; k < out.size(); ++k) {
    const P& a = out[k];
    const P& b = out[(k + 1) % out.size()];
    twice += a.s * b.t - b.s * a.t;
  }
  // (s, t) is an affine map of the triangle: areas scale by its area over 1/2.
  return std::fabs(twice) * 0.5 * length(cross(c[1] - c[0], c[2] - c[0]));
}

TEST(DeviationAreas, TriangleAreaAboveAgainstClipping) {
  // f = x on the unit right triangle: (1 - t)^2 / 2 above t, by hand.
  const std::array<Vec3, 3> unit = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  for (double t : {0.0, 0.3, 0.5, 0.99})
    EXPECT_NEAR(triangleAreaAbove(unit, {0, 1, 0}, t), 0.5 * (1 - t) * (1 - t), 1e-15) << t;
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const std::array<Vec3, 3> c = {Vec3{u(rng), u(rng), u(rng)}, Vec3{u(rng), u(rng), u(rng)},
                                   Vec3{u(rng), u(rng), u(rng)}};
    std::array<double, 3> f = {u(rng), u(rng), u(rng)};
    if (k % 5 == 0) f[1] = f[0];  // two equal values
    const double t = 1.2 * u(rng);
    EXPECT_NEAR(triangleAreaAbove(c, f, t), clippedArea(c, f, t), 1e-12) << k;
  }
}

TEST(DeviationAreas, FacetsWithoutAValueAreLeftOut) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  m.normals = {{0, 0, 1}, {0, 0, 1}};
  // Vertex 3 has no value: only the first facet (area 2) counts; its deviation runs from
  // -0.02 at vertex 0 to +0.02 at vertices 1 and 2.
  const DeviationAreas a = deviationAreas(m, {-0.02, 0.02, 0.02, NAN}, 0.01, 0.01);
  EXPECT_EQ(a.facetsLeftOut, 1);
  EXPECT_NEAR(a.measuredMm2, 2, 1e-15);
  // Above 0.01: the corner at vertex 0 below it is cut at 3/4 of both edges.
  EXPECT_NEAR(a.aboveLimitMm2, 2 * (1 - 0.75 * 0.75), 1e-15);
  // Below -0.01: the corner at vertex 0 cut at 1/4 of both edges.
  EXPECT_NEAR(a.gougedMm2, 2 * 0.25 * 0.25, 1e-15);
  EXPECT_EQ(deviationAreas(m, {-0.02, 0.02, 0.02, NAN}, NAN, 0.01).aboveLimitMm2, 0);
}

}  // namespace
}  // namespace scallop
