#include "raycast/grid_frame.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "base/input_error.h"

namespace scallop {

Vec3 GridFrame::pointToFrame(const Vec3& p) const {
  if (translationOnly()) return {p.x, p.y, p.z - origin.z};
  const Vec3 d = p - origin;
  return {dot(d, u), dot(d, v), dot(d, normal)};
}

Vec3 GridFrame::directionToFrame(const Vec3& d) const {
  if (translationOnly()) return d;
  return {dot(d, u), dot(d, v), dot(d, normal)};
}

Vec3 GridFrame::pointFromFrame(double x, double y, double w) const {
  if (translationOnly()) return {x, y, origin.z + w};
  return origin + x * u + y * v + w * normal;
}

GridSpec GridFrame::grid(double spacing) const {
  // The translation keeps the part's x and y: the map's cells are then the cells of the
  // map without a frame over the same rectangle, bit for bit.
  const double x0 = translationOnly() ? origin.x : 0, y0 = translationOnly() ? origin.y : 0;
  return gridCovering(x0, y0, x0 + sizeU, y0 + sizeV, spacing);
}

std::string GridFrame::describe() const {
  auto vec = [](const Vec3& p) {
    std::ostringstream out;
    out << std::setprecision(17) << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return out.str();
  };
  std::string text =
      "origin " + vec(origin) + " mm, u " + vec(u) + ", v " + vec(v) + ", normal " + vec(normal);
  if (std::isfinite(depth)) {
    std::ostringstream d;
    d << std::setprecision(17) << depth;
    text += ", depth " + d.str() + " mm";
  }
  return text + "; heights along normal from the plane through origin";
}

GridFrame makeGridFrame(const Vec3& origin, const Vec3& u, const Vec3& normal, double sizeU,
                        double sizeV, double depth, const char* field) {
  const std::string f = field;
  const double lu = length(u), ln = length(normal);
  if (!(lu > 0)) throw InputError(f + ".u", "must be a non-zero vector");
  if (!(ln > 0)) throw InputError(f + ".normal", "must be a non-zero vector");
  GridFrame frame;
  frame.origin = origin;
  // Unit vectors given exactly (+X, +Z) stay exactly so (translationOnly()).
  frame.u = lu == 1 ? u : u / lu;
  frame.normal = ln == 1 ? normal : normal / ln;
  const double c = dot(frame.u, frame.normal);
  if (!(std::fabs(c) <= 1e-9))
    throw InputError(f + ".normal", "must be at right angles to " + f +
                                        ".u (|u . normal| = " + std::to_string(std::fabs(c)) +
                                        " after normalising; at most 1e-9)");
  frame.v = cross(frame.normal, frame.u);
  frame.sizeU = sizeU;
  frame.sizeV = sizeV;
  frame.depth = depth;
  return frame;
}

ToolPath pathInFrame(const ToolPath& path, const GridFrame& frame) {
  ToolPath out = path;
  for (Move& m : out.moves) {
    for (Pose* pose : {&m.from, &m.to}) {
      pose->tip = frame.pointToFrame(pose->tip);
      pose->axis = frame.directionToFrame(pose->axis);
    }
  }
  // An arc's circle: its centre a point, u and v directions (n = u x v turns with them:
  // the frame's rotation is proper, v = normal x u).
  for (ArcMotion& arc : out.arcs) {
    arc.centre = frame.pointToFrame(arc.centre);
    arc.u = frame.directionToFrame(arc.u);
    arc.v = frame.directionToFrame(arc.v);
  }
  return out;
}

double stockTopInFrame(const Box3& stock, const GridFrame& frame) {
  double top = -HUGE_VAL;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{k & 1 ? stock.max.x : stock.min.x, k & 2 ? stock.max.y : stock.min.y,
                      k & 4 ? stock.max.z : stock.min.z};
    top = std::max(top, frame.pointToFrame(corner).z);
  }
  return top;
}

double stockExitHeight(const Box3& stock, const GridFrame& frame, double x, double y) {
  // The line p0 + w normal against the box's three slabs.
  const Vec3 p0 = frame.pointFromFrame(x, y, 0);
  const double p[3] = {p0.x, p0.y, p0.z}, n[3] = {frame.normal.x, frame.normal.y, frame.normal.z};
  const double lo[3] = {stock.min.x, stock.min.y, stock.min.z};
  const double hi[3] = {stock.max.x, stock.max.y, stock.max.z};
  double wLow = -HUGE_VAL, wHigh = HUGE_VAL;
  for (int a = 0; a < 3; ++a) {
    if (n[a] == 0) {
      if (p[a] < lo[a] || p[a] > hi[a]) return NAN;
      continue;
    }
    const double t1 = (lo[a] - p[a]) / n[a], t2 = (hi[a] - p[a]) / n[a];
    wLow = std::max(wLow, std::min(t1, t2));
    wHigh = std::min(wHigh, std::max(t1, t2));
  }
  if (wLow > wHigh || wHigh < -frame.depth) return NAN;
  return wHigh;
}

void fillFrameStock(ZMap& map, const Box3& stock, const GridFrame& frame) {
  const GridSpec& g = map.grid();
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double w = stockExitHeight(stock, frame, g.cellCentreX(i), g.cellCentreY(j));
      map.at(i, j) = std::isnan(w) ? kNoMaterial : w;
    }
}

FrameCellCounts finishFrameMap(ZMap& map, const GridFrame& frame) {
  FrameCellCounts counts;
  for (double& h : map.heights()) {
    if (h == kNoMaterial) {
      h = NAN;
      ++counts.voidCells;
    } else if (h < -frame.depth) {
      // Cut through: cutToFrameDepth (frame_depth.h) kept only such cells below -depth.
      h = -frame.depth;
      ++counts.cutThroughCells;
    }
  }
  return counts;
}

FrameCellCounts finishStockMap(ZMap& map) {
  FrameCellCounts counts;
  for (double& h : map.heights())
    if (h == kNoMaterial) {
      h = NAN;
      ++counts.voidCells;
    }
  return counts;
}

}  // namespace scallop
