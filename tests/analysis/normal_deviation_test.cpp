// Normal deviation on a design surface (analysis/normal_deviation.h) against closed
// forms: a ball cutter on passes along a cylinder with its axis along the normal (the
// union of the passes' solids in closed form), and a plane machined by a raster against
// the z-map of the same job.
#include "analysis/normal_deviation.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "analysis/vertex_normals.h"
#include "base/constants.h"
#include "base/input_error.h"
#include "raycast/simulation.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

constexpr double kDeg = kRadPerDeg;

// A design surface from a grid of points P(i, j), i < ni, j < nj, wound so that its
// normal is (P(i, j + 1) - P(i, j)) x (P(i + 1, j) - P(i, j)).
template <class Point>
TriangleMesh gridMesh(int ni, int nj, Point point) {
  std::vector<std::array<Vec3, 3>> soup;
  for (int i = 0; i + 1 < ni; ++i)
    for (int j = 0; j + 1 < nj; ++j) {
      soup.push_back({point(i, j), point(i, j + 1), point(i + 1, j)});
      soup.push_back({point(i + 1, j), point(i, j + 1), point(i + 1, j + 1)});
    }
  return meshFromTriangles(soup);
}

// Cylinder of radius rho about the x axis, ball cutter of radius R on passes along x
// with the axis along the cylinder's normal at angles theta_k = k dTheta: each pass's
// solid, across x, is the disc of radius R about (rho + R)(cos theta_k, sin theta_k)
// (its shank lies beyond the disc, away from the cylinder).
struct CylinderJob {
  double rho = 10, R = 2, dThetaDeg = 6;
  int firstPass = -5, lastPass = 20;  // passes from -30 to 120 degrees
  Cutter cutter = Cutter::make(CutterType::Ball, 2);
  ToolPath path;
  Box3 stock{{-30, -16, -16}, {30, 16, 16}};

  CylinderJob() {
    for (int k = firstPass; k <= lastPass; ++k) {
      const double t = k * dThetaDeg * kDeg;
      const Vec3 axis{0, std::cos(t), std::sin(t)};
      Move m;
      m.from = {Vec3{-25, rho * axis.y, rho * axis.z}, axis};
      m.to = {Vec3{25, rho * axis.y, rho * axis.z}, axis};
      path.moves.push_back(m);
    }
  }
  // The lowest w on the line p + w n in the union of the passes' discs (closed form).
  double lowestOnLine(const Vec3& p, const Vec3& n) const {
    double best = HUGE_VAL;
    for (int k = firstPass; k <= lastPass; ++k) {
      const double t = k * dThetaDeg * kDeg;
      const double qy = p.y - (rho + R) * std::cos(t), qz = p.z - (rho + R) * std::sin(t);
      const double a = n.y * n.y + n.z * n.z, b = 2 * (qy * n.y + qz * n.z);
      const double c = qy * qy + qz * qz - R * R, disc = b * b - 4 * a * c;
      if (disc >= 0) best = std::min(best, (-b - std::sqrt(disc)) / (2 * a));
    }
    return best;
  }
  double cuspHeight() const {
    const double h = 0.5 * dThetaDeg * kDeg;
    return (rho + R) * std::cos(h) - std::sqrt(R * R - std::pow((rho + R) * std::sin(h), 2)) - rho;
  }
};

TEST(NormalDeviation, BallPassesAlongACylinderGiveTheClosedFormOnTopAndOnTheSide) {
  const CylinderJob job;
  // Vertices every degree from -6 to 96 (0: the vertical side, normal +y; 90: the top),
  // five rows across x.
  const int nPhi = 103;
  auto point = [&](int i, int j) {
    const double phi = (j - 6) * kDeg;
    return Vec3{double(i - 2), job.rho * std::cos(phi), job.rho * std::sin(phi)};
  };
  const TriangleMesh design = gridMesh(5, nPhi, point);
  requireConsistentOrientation(design, "design");
  const NormalDeviation d = normalDeviation(job.cutter, job.path, job.stock, design, 1.0);
  EXPECT_EQ(d.unresolved, 0);
  EXPECT_EQ(d.noMaterial, 0);
  EXPECT_EQ(d.cutThrough, 0);
  double largest = -HUGE_VAL;
  int checked = 0;
  for (size_t v = 0; v < design.vertices.size(); ++v) {
    const Vec3& p = design.vertices[v];
    const double expected = job.lowestOnLine(p, d.normals[v]);
    ASSERT_NEAR(d.deviation[v], expected, 1e-6)
        << "vertex at " << p.x << ", " << p.y << ", " << p.z;
    ++checked;
    // Inner rows: the normal is the cylinder's (their facets are symmetric about them).
    if (std::fabs(p.x) <= 1) largest = std::max(largest, d.deviation[v]);
  }
  EXPECT_EQ(checked, 5 * nPhi);
  EXPECT_NEAR(largest, job.cuspHeight(), 1e-6);
  // The cusps next to the side (3 degrees) and to the top (87 degrees), on the middle row.
  for (int phiDeg : {3, 87}) {
    const size_t v = size_t(2 * nPhi + phiDeg + 6);  // meshFromTriangles welds in soup order
    ASSERT_NEAR(design.vertices[v].y, job.rho * std::cos(phiDeg * kDeg), 1e-12);
    EXPECT_NEAR(d.deviation[v], job.cuspHeight(), 1e-6) << phiDeg << " degrees";
  }
}

TEST(NormalDeviation, OneThreadGivesTheSameBits) {
  const CylinderJob job;
  const TriangleMesh design = gridMesh(4, 40, [&](int i, int j) {
    const double phi = (2.5 * j + 0.3 * i) * kDeg;  // every vertex its own normal
    return Vec3{double(i), job.rho * std::cos(phi), job.rho * std::sin(phi)};
  });
  const NormalDeviation all = normalDeviation(job.cutter, job.path, job.stock, design, 1.0);
  NormalDeviation one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = normalDeviation(job.cutter, job.path, job.stock, design, 1.0);
  }
  ASSERT_EQ(all.deviation.size(), one.deviation.size());
  for (size_t v = 0; v < all.deviation.size(); ++v)
    EXPECT_EQ(std::memcmp(&all.deviation[v], &one.deviation[v], sizeof(double)), 0) << v;
  EXPECT_EQ(all.exactEvaluations, one.exactEvaluations);
  EXPECT_EQ(all.unresolved + all.noMaterial, 0);
}

TEST(NormalDeviation, PlaneMachinedByARasterIsTheZMapLessThePlane) {
  const Cutter cutter = Cutter::make(CutterType::Ball, 1);
  const Box3 stock{{0, 0, -3}, {10, 6, 0}};
  RasterSpec raster;
  raster.stepOver = 0.7;
  raster.depth = 0.4;
  const ToolPath path = makeRaster(cutter, stock, raster);
  const double spacing = 0.125;
  const GridSpec grid = gridCovering(0, 0, 10, 6, spacing);
  const ZMap map = simulate(cutter, path, stock, grid).map;
  const double planeZ = -0.45;  // below the passes' floor (-0.4): every line is cut
  const int i0 = 8, j0 = 4;
  auto point = [&](int i, int j) {
    return Vec3{grid.cellCentreX(i0 + j), grid.cellCentreY(j0 + i), planeZ};
  };
  // Rows along y, columns along x: the normal (dx x dy) is +z.
  const TriangleMesh design = gridMesh(32, 64, point);
  const NormalDeviation d = normalDeviation(cutter, path, stock, design, 1.0);
  EXPECT_EQ(d.unresolved + d.noMaterial + d.cutThrough, 0);
  for (size_t v = 0; v < design.vertices.size(); ++v) {
    const Vec3& p = design.vertices[v];
    ASSERT_EQ(d.normals[v].z, 1.0);
    const int64_t i = std::llround((p.x - grid.cellCentreX(0)) / spacing);
    const int64_t j = std::llround((p.y - grid.cellCentreY(0)) / spacing);
    ASSERT_NEAR(d.deviation[v], map.at(i, j) - planeZ, 1e-9) << "cell " << i << ", " << j;
  }
}

TEST(NormalDeviation, AMoveReachingTheLineFromBehindIsUnresolvedNotWrong) {
  // A facet facing down (-z) at z = 0, a ball coming from above to 0.5 below it: along
  // the line's normal the tool's axis points away (k = -1 in the line's frame).
  const TriangleMesh design = meshFromTriangles({{Vec3{0, 0, 0}, Vec3{0, 4, 0}, Vec3{4, 0, 0}}});
  ASSERT_LT(design.normals[0].z, 0);
  ToolPath path;
  Move m;
  m.from = {Vec3{-5, 1, -0.5}, Vec3{0, 0, 1}};
  m.to = {Vec3{5, 1, -0.5}, Vec3{0, 0, 1}};
  path.moves.push_back(m);
  const Box3 stock{{-6, -6, -5}, {6, 6, 5}};
  const NormalDeviation d =
      normalDeviation(Cutter::make(CutterType::Ball, 1), path, stock, design, 1.0);
  // The ball (y in [0, 2]) reaches the lines of (0, 0, 0) and (4, 0, 0), not that of
  // (0, 4, 0), which keeps the stock down to z = -5.
  EXPECT_EQ(d.unresolved, 2);
  for (size_t v = 0; v < 3; ++v) {
    if (design.vertices[v].y == 4)
      EXPECT_EQ(d.deviation[v], 5.0);
    else
      EXPECT_TRUE(std::isnan(d.deviation[v]));
  }
}

TEST(NormalDeviation, LinesMissingTheStockHoldNoMaterialAndDeepCutsAreClamped) {
  const TriangleMesh design = meshFromTriangles({{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}},
                                                 {Vec3{20, 0, 0}, Vec3{21, 0, 0}, Vec3{20, 1, 0}}});
  ToolPath path;
  Move m;  // a flat cutter 2 mm below the first facet, under the whole of it
  m.from = {Vec3{-3, 0, -2}, Vec3{0, 0, 1}};
  m.to = {Vec3{3, 0, -2}, Vec3{0, 0, 1}};
  path.moves.push_back(m);
  const Box3 stock{{-5, -5, -5}, {5, 5, 1}};  // the second facet is outside it
  const NormalDeviation d =
      normalDeviation(Cutter::make(CutterType::Flat, 3), path, stock, design, 0.5);
  EXPECT_EQ(d.cutThrough, 3);
  EXPECT_EQ(d.noMaterial, 3);
  for (size_t v = 0; v < 3; ++v) EXPECT_EQ(d.deviation[v], -0.5);
  for (size_t v = 3; v < 6; ++v) EXPECT_TRUE(std::isnan(d.deviation[v]));
}

TEST(VertexNormals, InconsistentOrientationNamesTheFacet) {
  // Two facets sharing the edge (1, 0, 0)-(0, 1, 0), the second wound like the first.
  const TriangleMesh mesh = meshFromTriangles({{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}},
                                               {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 1}}});
  try {
    requireConsistentOrientation(mesh, "part.stl");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "part.stl");
    EXPECT_NE(std::string(e.what()).find("facet 2"), std::string::npos) << e.what();
  }
}

// A closed tetrahedron wound outwards passes; the same wound inwards (every facet's
// corners the other way round) is refused naming the file and its signed volume, -1/6.
TEST(VertexNormals, AClosedSurfaceFacingInwardsIsRefused) {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  const std::vector<std::array<Vec3, 3>> outwards = {{o, y, x}, {o, x, z}, {o, z, y}, {x, y, z}};
  requireConsistentOrientation(meshFromTriangles(outwards), "part.stl");
  std::vector<std::array<Vec3, 3>> inwards = outwards;
  for (auto& f : inwards) std::swap(f[1], f[2]);
  try {
    requireConsistentOrientation(meshFromTriangles(inwards), "part.stl");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "part.stl");
    EXPECT_NE(std::string(e.what()).find("face inwards"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-0.1666666667"), std::string::npos) << e.what();
  }
}

TEST(VertexNormals, AreaWeightedMeanOfTheAdjacentFacets) {
  // A right triangle of area 1/2 facing +z and one of area 1 facing +x share the edge on the y
  // axis.
  const TriangleMesh mesh = meshFromTriangles({{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}},
                                               {Vec3{0, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 2}}});
  const std::vector<Vec3> n = areaWeightedVertexNormals(mesh);
  const double s = std::sqrt(5.0);  // (0.5 z + 1 x) normalised
  EXPECT_NEAR(n[0].x, 2 / s, 1e-15);
  EXPECT_NEAR(n[0].z, 1 / s, 1e-15);
  EXPECT_EQ(n[1].z, 1.0);  // (1, 0, 0) touches the first facet only
}

}  // namespace
}  // namespace scallop
