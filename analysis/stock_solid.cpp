#include "analysis/stock_solid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "raycast/grid_frame.h"

namespace scallop {

void checkClosedSolid(const TriangleMesh& mesh, const std::string& field) {
  // Each directed edge (a, b) must occur once, and its reverse (b, a) once: then every
  // edge has exactly two facets, oriented alike.
  std::map<std::pair<uint32_t, uint32_t>, size_t> directed;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& f = mesh.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const auto key = std::make_pair(f[e], f[(e + 1) % 3]);
      const auto [it, added] = directed.emplace(key, t);
      if (!added)
        throw InputError(field, "is not a closed solid: facets " + std::to_string(it->second + 1) +
                                    " and " + std::to_string(t + 1) +
                                    " run along the same edge in the same direction "
                                    "(inconsistent orientation, or an edge of more than two "
                                    "facets)");
    }
  }
  for (const auto& [edge, t] : directed)
    if (!directed.count({edge.second, edge.first})) {
      const Vec3 a = mesh.vertices[edge.first], b = mesh.vertices[edge.second];
      throw InputError(field, "is not a closed solid: the edge of facet " + std::to_string(t + 1) +
                                  " from (" + std::to_string(a.x) + ", " + std::to_string(a.y) +
                                  ", " + std::to_string(a.z) + ") to (" + std::to_string(b.x) +
                                  ", " + std::to_string(b.y) + ", " + std::to_string(b.z) +
                                  ") belongs to no other facet (a hole)");
    }
}

StockSolid::StockSolid(TriangleMesh mesh)
    : mesh_(std::move(mesh)), index_(std::make_unique<MeshIndex>(mesh_)) {}

double StockSolid::topAt(double x, double y) const {
  double z = 0;
  uint32_t triangle = 0;
  return index_->topHeight(x, y, z, triangle) ? z : NAN;
}

void StockSolid::fillHeights(ZMap& map) const {
  const GridSpec& g = map.grid();
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double z = topAt(g.cellCentreX(i), g.cellCentreY(j));
      map.at(i, j) = std::isnan(z) ? kNoMaterial : z;
    }
}

namespace {

struct Point2 {
  double x, y;
};

double cross2(Point2 o, Point2 a, Point2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double pointToSegment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double d1 = cross2(c, d, a), d2 = cross2(c, d, b);
  const double d3 = cross2(a, b, c), d4 = cross2(a, b, d);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Distance in xy from the convex polygon `poly` to the segment a-b (0 if they meet).
double polygonToSegment(const std::vector<Point2>& poly, Point2 a, Point2 b) {
  // The segment's ends inside the polygon (either winding).
  auto inside = [&](Point2 p) {
    bool pos = false, neg = false;
    for (size_t k = 0; k < poly.size(); ++k) {
      const double c = cross2(poly[k], poly[(k + 1) % poly.size()], p);
      pos |= c > 0;
      neg |= c < 0;
    }
    return !(pos && neg);
  };
  // A facet seen edge-on (a vertical facet) clips to a polygon of no area: only its
  // edges count.
  double area = 0;
  for (size_t k = 1; k + 1 < poly.size(); ++k) area += cross2(poly[0], poly[k], poly[k + 1]);
  if (area != 0 && (inside(a) || inside(b))) return 0;
  double best = HUGE_VAL;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Point2 p = poly[k], q = poly[(k + 1) % poly.size()];
    if (segmentsCross(p, q, a, b)) return 0;
    best =
        std::min({best, pointToSegment(p, a, b), pointToSegment(a, p, q), pointToSegment(b, p, q)});
  }
  return best;
}

}  // namespace

namespace {

// The highest point of the facet part `poly` (convex, in 3D, above the clipping height)
// whose xy lies within `reach` of the segment a-b: the largest of a linear height over
// a convex set (the polygon and the capsule about a-b), so at a polygon corner inside
// the capsule, where a polygon edge crosses the capsule's boundary, or at the
// capsule's own highest point (a or b moved `reach` uphill) inside the polygon. The
// crossings are found by bisection on the edge's distance (convex along it) to 1e-12
// of the edge. -HUGE_VAL z when no such point exists.
Vec3 highestWithin(const std::vector<Vec3>& poly, Point2 a, Point2 b, double reach) {
  Vec3 best{0, 0, -HUGE_VAL};
  auto take = [&](const Vec3& p) {
    if (p.z > best.z) best = p;
  };
  auto dist = [&](const Vec3& p) { return pointToSegment({p.x, p.y}, a, b); };
  const size_t n = poly.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec3 p = poly[k], q = poly[(k + 1) % n];
    if (dist(p) <= reach) take(p);
    auto at = [&](double s) { return p + (q - p) * s; };
    // The edge's closest point (golden section on a convex function), then the
    // crossings on either side of it.
    double lo = 0, hi = 1;
    for (int it = 0; it < 80 && hi - lo > 1e-13; ++it) {
      const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
      if (dist(at(m1)) <= dist(at(m2)))
        hi = m2;
      else
        lo = m1;
    }
    const double sMin = 0.5 * (lo + hi);
    if (dist(at(sMin)) > reach) continue;
    take(at(sMin));
    for (const double outer : {0.0, 1.0}) {
      if (dist(at(outer)) <= reach) continue;  // the corner itself is in
      double in = sMin, out = outer;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (in + out);
        (dist(at(mid)) <= reach ? in : out) = mid;
      }
      take(at(in));
    }
  }
  // The plane's uphill direction in xy (none for a facet seen edge-on or level).
  const Vec3 normal = cross(poly[1] - poly[0], poly[2] - poly[0]);
  if (n >= 3 && normal.z != 0) {
    const double gx = -normal.x / normal.z, gy = -normal.y / normal.z, g = std::hypot(gx, gy);
    const std::vector<Point2> xy = [&] {
      std::vector<Point2> out;
      for (const Vec3& p : poly) out.push_back({p.x, p.y});
      return out;
    }();
    for (const Point2 end : {a, b}) {
      const Point2 c = g > 0 ? Point2{end.x + reach * gx / g, end.y + reach * gy / g} : end;
      bool pos = false, neg = false;
      for (size_t k = 0; k < n; ++k) {
        const double s = cross2(xy[k], xy[(k + 1) % n], c);
        pos |= s > 0;
        neg |= s < 0;
      }
      if (!(pos && neg))
        take({c.x, c.y, poly[0].z + gx * (c.x - poly[0].x) + gy * (c.y - poly[0].y)});
    }
  }
  return best;
}

}  // namespace

bool StockSolid::reachesAbove(const Vec3& a, const Vec3& b, double reach, double z,
                              Vec3* highest) const {
  const Point2 a2{a.x, a.y}, b2{b.x, b.y};
  bool found = false;
  Vec3 top{0, 0, -HUGE_VAL};
  std::vector<Point2> clipped;
  std::vector<Vec3> clipped3;
  for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto c = mesh_.corners(t);
    // The facet's part above z (Sutherland-Hodgman against one plane).
    clipped.clear();
    clipped3.clear();
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = c[k], q = c[(k + 1) % 3];
      if (p.z > z) clipped3.push_back(p);
      if ((p.z > z) != (q.z > z)) clipped3.push_back(p + (q - p) * ((z - p.z) / (q.z - p.z)));
    }
    for (const Vec3& p : clipped3) clipped.push_back({p.x, p.y});
    if (clipped.empty() || polygonToSegment(clipped, a2, b2) >= reach) continue;
    found = true;
    if (!highest) break;
    const Vec3 h = highestWithin(clipped3, a2, b2, reach);
    if (h.z > top.z) top = h;
  }
  if (highest) *highest = top;
  return found;
}

}  // namespace scallop
