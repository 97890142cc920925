#include "analysis/gouge_check.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "raycast/simulation.h"

namespace scallop {

bool vertexInside(const Vec3& v, const Cylinder& c, double tolerance) {
  const Vec3 q = v - c.tip;
  const double s = dot(q, c.axis);
  if (s < 0 || s > c.length) return false;
  return c.radius - length(q - c.axis * s) > tolerance;
}

namespace {

struct SlabPoint {
  Vec3 q;    // position relative to the tip, mm
  double s;  // q . axis
};

// Sutherland-Hodgman against one side of the slab: keeps s >= bound (keepAbove) or
// s <= bound. Crossing points get s = bound exactly.
int clip(const SlabPoint* in, int n, SlabPoint* out, double bound, bool keepAbove) {
  auto inside = [&](double s) { return keepAbove ? s >= bound : s <= bound; };
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const SlabPoint& a = in[i];
    const SlabPoint& b = in[(i + 1) % n];
    const bool ia = inside(a.s), ib = inside(b.s);
    if (ia) out[m++] = a;
    if (ia != ib) {
      const double t = (bound - a.s) / (b.s - a.s);
      out[m++] = {a.q + (b.q - a.q) * t, bound};
    }
  }
  return m;
}

}  // namespace

double trianglePenetration(const std::array<Vec3, 3>& tri, const Cylinder& c) {
  SlabPoint p0[3], p1[4], p2[5];
  for (int k = 0; k < 3; ++k) {
    const Vec3 q = tri[size_t(k)] - c.tip;
    p0[k] = {q, dot(q, c.axis)};
  }
  const int n1 = clip(p0, 3, p1, 0.0, true);
  if (n1 == 0) return 0;
  const int n = clip(p1, n1, p2, c.length, false);
  if (n == 0) return 0;

  // Radial parts: the projection of the clipped polygon along the axis (convex).
  Vec3 r[5];
  for (int i = 0; i < n; ++i) r[i] = p2[i].q - c.axis * p2[i].s;

  // Is the axis (the origin of the projection) inside the projected polygon? Then the
  // axis line meets the polygon and the distance is 0.
  double area = 0;
  double side[5];
  for (int i = 0; i < n; ++i) {
    const Vec3& a = r[i];
    const Vec3& b = r[(i + 1) % n];
    area += dot(cross(a, b), c.axis);
    side[i] = dot(cross(b - a, -a), c.axis);
  }
  double dmin = HUGE_VAL;
  if (area != 0) {
    bool inside = true;
    for (int i = 0; i < n; ++i) inside = inside && (area > 0 ? side[i] >= 0 : side[i] <= 0);
    if (inside) dmin = 0;
  }
  // Otherwise the closest point is on an edge: |r0 + t (r1 - r0)| is a convex
  // quadratic in t, minimised in closed form and clamped to the edge.
  for (int i = 0; i < n && dmin > 0; ++i) {
    const Vec3& a = r[i];
    const Vec3 d = r[(i + 1) % n] - a;
    const double dd = dot(d, d);
    const double t = dd > 0 ? std::clamp(-dot(a, d) / dd, 0.0, 1.0) : 0.0;
    dmin = std::min(dmin, length(a + d * t));
  }
  return std::max(0.0, c.radius - dmin);
}

Penetration cylinderPenetration(const TriangleMesh& mesh, const std::vector<uint32_t>& candidates,
                                const Cylinder& c) {
  Penetration p;
  for (uint32_t t : candidates) {
    const double d = trianglePenetration(mesh.corners(t), c);
    if (d > p.depth) p.depth = d, p.triangle = t;
  }
  return p;
}

ZMap designHeights(const MeshIndex& index, const GridSpec& grid) {
  ZMap map(grid, std::nan(""));
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, grid.ny),
                    [&](const tbb::blocked_range<int64_t>& rows) {
                      for (int64_t j = rows.begin(); j < rows.end(); ++j)
                        for (int64_t i = 0; i < grid.nx; ++i) {
                          double z;
                          uint32_t t;
                          if (index.topHeight(grid.cellCentreX(i), grid.cellCentreY(j), z, t))
                            map.at(i, j) = z;
                        }
                    });
  return map;
}

GougeMap gougeMap(const MeshIndex& index, const Cutter& cutter, const ToolPath& path,
                  const GridSpec& grid, const GougeMapOptions& options) {
  GougeMap g;
  g.design = designHeights(index, grid);
  const Box3 box = index.mesh().bounds();
  // Above the whole design surface: a cell left at stockTop was never reached.
  g.stockTop = box.max.z + 1.0;
  if (path.cuttingMoves() == 0) {
    g.machined = ZMap(grid, g.stockTop);
  } else {
    Box3 stock;
    stock.min = {grid.originX, grid.originY, box.min.z - 1.0};
    stock.max = {grid.originX + grid.nx * grid.spacing, grid.originY + grid.ny * grid.spacing,
                 g.stockTop};
    SimulationOptions sim;
    sim.tileSize = options.tileSize > 0 ? options.tileSize : 0.5 * cutter.radius;
    SimulationResult r = simulate(cutter, path, stock, grid, sim);
    g.stats.sweptSegments = r.scene.segments;
    g.machined = std::move(r.map);
  }

  g.overCut = ZMap(grid, 0.0);
  GougeMapStats& s = g.stats;
  double overSum = 0, underSum = 0;
  for (int64_t j = 0; j < grid.ny; ++j)
    for (int64_t i = 0; i < grid.nx; ++i) {
      const double design = g.design.at(i, j);
      if (std::isnan(design)) continue;
      ++s.designCells;
      const double machined = g.machined.at(i, j);
      if (machined >= g.stockTop) {
        ++s.untouchedCells;
        continue;
      }
      const double diff = machined - design;
      s.maxOverCut = std::max(s.maxOverCut, -diff);
      s.maxUnderCut = std::max(s.maxUnderCut, diff);
      if (diff < -options.tolerance) {
        ++s.overCutCells;
        overSum += -diff;
        g.overCut.at(i, j) = -diff;
      } else if (diff > options.tolerance) {
        ++s.underCutCells;
        underSum += diff;
      }
    }
  s.meanOverCut = s.overCutCells ? overSum / double(s.overCutCells) : 0;
  s.meanUnderCut = s.underCutCells ? underSum / double(s.underCutCells) : 0;
  return g;
}

}  // namespace scallop
