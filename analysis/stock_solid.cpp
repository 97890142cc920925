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

bool StockSolid::reachesAbove(const Vec3& a, const Vec3& b, double reach, double z,
                              double* highest) const {
  const Point2 a2{a.x, a.y}, b2{b.x, b.y};
  bool found = false;
  double top = -HUGE_VAL;
  std::vector<Point2> clipped;
  for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto c = mesh_.corners(t);
    // The facet's part above z (Sutherland-Hodgman against one plane), in xy.
    clipped.clear();
    double facetTop = -HUGE_VAL;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = c[k], q = c[(k + 1) % 3];
      if (p.z > z) clipped.push_back({p.x, p.y}), facetTop = std::max(facetTop, p.z);
      if ((p.z > z) != (q.z > z)) {
        const double s = (z - p.z) / (q.z - p.z);
        clipped.push_back({p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)});
      }
    }
    if (clipped.empty() || facetTop <= top) continue;
    if (polygonToSegment(clipped, a2, b2) < reach) {
      found = true;
      top = facetTop;
    }
  }
  if (highest) *highest = top;
  return found;
}

}  // namespace scallop
