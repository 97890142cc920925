// Seed 004's strategy (analysis/peripheral_strategy.h) and the exact check on surfaces
// whose answer is known by hand: a plane, a trough narrower than the cutter, a concave
// crease between two large facets, and a path pushed a known depth into a plane.
#include "analysis/peripheral_strategy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/analytic_surfaces.h"
#include "base/constants.h"

namespace scallop {
namespace {

// Two triangles per rectangle, counter-clockwise seen from the +normal side.
void addQuad(std::vector<std::array<Vec3, 3>>& soup, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  soup.push_back({a, b, c});
  soup.push_back({a, c, d});
}

// The plane z = slopeX x + slopeY y over nx x ny square cells of `cell` mm from the origin.
TriangleMesh planeMesh(int nx, int ny, double cell, double slopeX, double slopeY) {
  std::vector<std::array<Vec3, 3>> soup;
  auto p = [&](double x, double y) { return Vec3{x, y, slopeX * x + slopeY * y}; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      addQuad(soup, p(cell * i, cell * j), p(cell * i + cell, cell * j),
              p(cell * i + cell, cell * j + cell), p(cell * i, cell * j + cell));
  return meshFromTriangles(soup);
}

TEST(PeripheralStrategy, TiltedPlaneIsMachinableWithoutGouge) {
  // z = 0.3 x + 0.2 y over 60 x 50 mm, 12 x 10 cells.
  const TriangleMesh mesh = planeMesh(12, 10, 5, 0.3, 0.2);
  const MeshIndex index(mesh);
  const Cutter cutter = Cutter::make(CutterType::Flat, 4, 0, 12);
  for (InclinationAxis axis : {InclinationAxis::Normal, InclinationAxis::Feed}) {
    StrategyOptions o;
    o.inclinationAxis = axis;
    o.ccStep = 1.3;
    const StrategyResult r = runPeripheralStrategy(index, cutter, o);
    ASSERT_GT(r.summary.ccPoints, 100u);
    EXPECT_EQ(r.summary.nonMachinable, 0u);
    EXPECT_EQ(r.summary.freeInitial, r.summary.ccPoints);
    EXPECT_EQ(r.summary.gougingPostures, 0u);
    EXPECT_DOUBLE_EQ(r.summary.machinablePct(), 100.0);
    for (const PostureResult& q : r.postures) {
      EXPECT_LE(q.exactDepth, 1e-9);
      // The flank is tangent at the cc-point: the axis is R from it along the normal.
      const Vec3 d = q.cc.point - q.pose.tip;
      EXPECT_NEAR(length(d - q.pose.axis * dot(d, q.pose.axis)), 4.0, 1e-12);
      EXPECT_NEAR(dot(q.pose.axis, q.cc.normal), 0.0, 1e-12);
    }
  }
}

TEST(PeripheralStrategy, FlatPlaneFromTheGenerator) {
  SurfaceSpec spec;
  spec.shape = SurfaceShape::Plane;
  spec.sizeX = 80, spec.sizeY = 60, spec.facets = 2000;
  const TriangleMesh mesh = makeAnalyticSurface(spec);
  const MeshIndex index(mesh);
  const StrategyResult r =
      runPeripheralStrategy(index, Cutter::make(CutterType::Flat, 5, 0, 20), {});
  ASSERT_GT(r.summary.ccPoints, 0u);
  EXPECT_EQ(r.summary.freeInitial, r.summary.ccPoints);
  EXPECT_EQ(r.summary.planes, 3u);  // 60 mm / 20 mm
  EXPECT_LE(r.summary.maxDepth, 1e-9);
  for (const PostureResult& q : r.postures) EXPECT_LE(q.exactDepth, 1e-9);
}

// A groove of radius r = 3 along y, crossed by the feed along x, machined with R = 5:
// a cylinder tangent inside a circle smaller than itself always cuts into the material
// on both sides of the contact, and tilting the axis within the tangent plane (or
// reversing it) only flattens its section further, so every cc-point inside the
// groove is non-machinable; on the flat the cutter lies on the plane and is free.
TEST(PeripheralStrategy, TroughNarrowerThanTheCutterIsNonMachinable) {
  SurfaceSpec spec;
  spec.shape = SurfaceShape::Trough;
  spec.sizeX = 60, spec.sizeY = 40, spec.facets = 2 * 240 * 160;  // 0.25 mm cells
  spec.troughRadius = 3, spec.height = 2;
  const TriangleMesh mesh = makeAnalyticSurface(spec);
  const MeshIndex index(mesh);
  const double R = 5;
  const StrategyResult r =
      runPeripheralStrategy(index, Cutter::make(CutterType::Flat, R, 0, 20), {});
  const double rim = std::sqrt(3.0 * 3.0 - 1.0 * 1.0);  // half-width of the groove at z = 0
  size_t inGroove = 0, onFlat = 0;
  for (const PostureResult& q : r.postures) {
    const double u = std::fabs(q.cc.point.x - 30);
    if (u < rim - 0.5) {
      ++inGroove;
      EXPECT_EQ(q.verdict, PostureClass::NonMachinable) << "x = " << q.cc.point.x;
      EXPECT_GT(q.initialExactDepth, 0.0);
    } else if (u > rim + 0.5) {
      ++onFlat;
      EXPECT_EQ(q.verdict, PostureClass::FreeInitial) << "x = " << q.cc.point.x;
      EXPECT_LE(q.exactDepth, 1e-9);
    }
  }
  EXPECT_GT(inGroove, 20u);
  EXPECT_GT(onFlat, 200u);
  EXPECT_GT(r.summary.nonMachinablePct(), 0.0);
}

// Concave crease between two large facets: A is z = 0 for x in [-20, 0], B rises at
// theta = 30 deg for x in [0, 20]; y in [0, 40]. The feed runs along x, so the cutter
// (R = 5, L = 10) lies along -y, parallel to the crease. Tangent to A at distance a
// from the crease, its axis is the line (x, z) = (-a, R); B's plane is at distance
// a sin(theta) + R cos(theta) from it, so the cutter cuts B by
//     depth(a) = R (1 - cos theta) - a sin theta     (a <= R tan(theta/2))
// through B's interior: every vertex is at least sqrt(a^2 + R^2) from the axis. By
// the wedge's mirror symmetry the same holds on B with a = distance along B.
TEST(PeripheralStrategy, CreaseBetweenLargeFacetsGougesUnseenByTheVertexTest) {
  const double th = degToRad(30), R = 5;
  const double t = std::tan(th);
  std::vector<std::array<Vec3, 3>> soup;
  addQuad(soup, {-20, 0, 0}, {0, 0, 0}, {0, 40, 0}, {-20, 40, 0});
  addQuad(soup, {0, 0, 0}, {20, 0, 20 * t}, {20, 40, 20 * t}, {0, 40, 0});
  const TriangleMesh mesh = meshFromTriangles(soup);
  const MeshIndex index(mesh);
  const Cutter cutter = Cutter::make(CutterType::Flat, R, 0, 10);
  auto expected = [&](double a) {
    return std::max(0.0, R * (1 - std::cos(th)) - a * std::sin(th));
  };

  // One posture by hand: a = 0.5 mm on A, depth 5 (1 - cos 30) - 0.25 = 0.41987298...
  const Pose pose =
      peripheralPose({-0.5, 20, 0}, {0, 0, 1}, {1, 0, 0}, 0, InclinationAxis::Normal, cutter, 0);
  EXPECT_NEAR(pose.tip.z, R, 1e-15);
  EXPECT_NEAR(pose.axis.y, -1.0, 1e-15);
  std::vector<uint32_t> all = {0, 1, 2, 3};
  const Cylinder cyl{pose.tip, pose.axis, R, 10};
  EXPECT_NEAR(cylinderPenetration(mesh, all, cyl).depth, 5 * (1 - std::sqrt(3.0) / 2) - 0.25, 1e-6);
  for (const Vec3& v : mesh.vertices) EXPECT_FALSE(vertexInside(v, cyl, 1e-9));

  StrategyOptions o;
  o.ccStep = 0.25;
  const StrategyResult r = runPeripheralStrategy(index, cutter, o);
  size_t gouging = 0;
  double deepest = 0;
  for (const PostureResult& q : r.postures) {
    EXPECT_EQ(q.verdict, PostureClass::FreeInitial);
    EXPECT_TRUE(q.vertexFree);
    const double a = q.cc.point.x <= 0 ? -q.cc.point.x : q.cc.point.x / std::cos(th);
    EXPECT_NEAR(q.exactDepth, expected(a), 1e-6) << "cc x = " << q.cc.point.x;
    gouging += q.exactDepth > o.gougeTolerance;
    deepest = std::max(deepest, expected(a));
  }
  EXPECT_GT(gouging, 0u);
  EXPECT_EQ(r.summary.gougingPostures, gouging);
  EXPECT_EQ(r.summary.missedByVertexTest, gouging);
  EXPECT_NEAR(r.summary.maxDepth, deepest, 1e-6);
  EXPECT_EQ(r.summary.nonMachinable, 0u);
}

// The gouge map of a path pushed delta into the surface along the normal. On the
// plane z = 0 the flank's lowest line is at -delta exactly; on a tilted plane the
// z-map (vertical) depth is delta / n_z.
void expectOffsetDepth(double slopeX, double delta) {
  const TriangleMesh mesh = planeMesh(4, 4, 10, slopeX, 0);
  const MeshIndex index(mesh);
  const Cutter cutter = Cutter::make(CutterType::Flat, 3, 0, 10);
  StrategyOptions o;
  o.ccStep = 2;
  o.ccAxialPosition = 0.5;
  const StrategyResult r = runPeripheralStrategy(index, cutter, o);
  ASSERT_EQ(r.summary.nonMachinable, 0u);
  const GridSpec grid = gridCovering(0, 0, 40, 40, 0.1);
  GougeMapOptions mo;
  mo.tolerance = 1e-6;

  const GougeMap clean = gougeMap(index, cutter, r.path, grid, mo);
  EXPECT_EQ(clean.stats.overCutCells, 0);
  EXPECT_LE(clean.stats.maxOverCut, 1e-9);
  EXPECT_GT(clean.stats.designCells - clean.stats.untouchedCells, 10000);

  const Vec3 n = normalize(Vec3{-slopeX, 0, 1});
  ToolPath pushed = r.path;
  for (Move& m : pushed.moves) m.from.tip -= n * delta, m.to.tip -= n * delta;
  const GougeMap g = gougeMap(index, cutter, pushed, grid, mo);
  EXPECT_NEAR(g.stats.maxOverCut, delta / n.z, 1e-4);
  EXPECT_GT(g.stats.overCutCells, 10000);
}

TEST(GougeMap, PathPushedIntoAPlaneByDelta) {
  expectOffsetDepth(0.0, 0.05);
}
TEST(GougeMap, PathPushedIntoATiltedPlaneByDelta) {
  expectOffsetDepth(0.25, 0.02);
}

TEST(GougeMap, DesignHeightsAreThePlanesInDouble) {
  std::vector<std::array<Vec3, 3>> soup;
  addQuad(soup, {0, 0, 1}, {10, 0, 1 + 0.7 * 10}, {10, 10, 1 + 0.7 * 10 - 0.3 * 10},
          {0, 10, 1 - 0.3 * 10});
  const TriangleMesh mesh = meshFromTriangles(soup);
  const MeshIndex index(mesh);
  const ZMap z = designHeights(index, gridCovering(0, 0, 10, 10, 0.37));
  for (int64_t j = 0; j < z.ny(); ++j)
    for (int64_t i = 0; i < z.nx(); ++i) {
      const double x = z.grid().cellCentreX(i), y = z.grid().cellCentreY(j);
      if (x > 10 || y > 10) {
        EXPECT_TRUE(std::isnan(z.at(i, j)));
        continue;
      }
      EXPECT_NEAR(z.at(i, j), 1 + 0.7 * x - 0.3 * y, 1e-12);
    }
}

}  // namespace
}  // namespace scallop
