#include "sweep/tool_path_sweep.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "sweep/input_error.h"

namespace scallop {

namespace {

// Spherical linear interpolation between unit axes a0 and a1 (angle phi apart).
Vec3 slerp(const Vec3& a0, const Vec3& a1, double phi, double t) {
  const double s = std::sin(phi);
  return normalize(a0 * (std::sin((1 - t) * phi) / s) + a1 * (std::sin(t * phi) / s));
}

// True when segment b continues segment a along the same line, in the same sense,
// with the same axis: then the union of their swept solids is the swept solid of the
// merged segment, so merging is exact.
bool continues(const SweptSegment& a, const Vec3& bStart, const Vec3& bEnd, const Vec3& axis) {
  if (a.axis() != axis || a.end() != bStart) return false;
  const Vec3 da = a.end() - a.start(), db = bEnd - bStart;
  const double la = length(da), lb = length(db);
  if (la == 0 || lb == 0) return la == 0 && lb == 0 ? false : true;
  return length(cross(da, db)) <= 1e-12 * la * lb && dot(da, db) > 0;
}

}  // namespace

std::vector<SweptSegment> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                        const SweepOptions& options) {
  std::vector<SweptSegment> out;
  auto push = [&](const Vec3& p0, const Vec3& p1, const Vec3& axis) {
    if (!out.empty() && continues(out.back(), p0, p1, axis)) {
      const Vec3 start = out.back().start();
      // Keep a zero-length predecessor's position out of the merged move.
      out.back() =
          SweptSegment(cutter, length(out.back().end() - start) == 0 ? p0 : start, p1, axis);
      return;
    }
    out.emplace_back(cutter, p0, p1, axis);
  };

  // Farthest distance of a cutter point from the tip: a rotation by delta moves no
  // point of the cutter by more than reach * delta.
  const double reach = std::hypot(cutter.fluteLength, cutter.radius);
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& mv = path.moves[k];
    if (mv.rapid) continue;
    const Vec3 a0 = normalize(mv.from.axis), a1 = normalize(mv.to.axis);
    const double phi = std::acos(std::clamp(dot(a0, a1), -1.0, 1.0));
    if (phi <= 1e-12) {
      push(mv.from.tip, mv.to.tip, a0);
      continue;
    }
    if (phi > 3.14159265358979323846 - 1e-9)
      throw InputError("path move " + std::to_string(k + 1),
                       "the axis turns by 180 degrees; the rotation is undefined");
    // Piece i holds the axis of its midpoint, so the axis is off by at most phi/(2N):
    // N = ceil(reach * phi / (2 tol)) keeps every cutter point within tol.
    const double pieces = std::ceil(reach * phi / (2 * options.axisTolerance));
    if (pieces > 1e6)
      throw InputError("path move " + std::to_string(k + 1),
                       "the axis turns too much for the tolerance " +
                           std::to_string(options.axisTolerance) + " mm (" +
                           std::to_string(pieces) + " pieces)");
    const int n = std::max(1, int(pieces));
    for (int i = 0; i < n; ++i) {
      const double t0 = double(i) / n, t1 = double(i + 1) / n;
      const Vec3 p0 = mv.from.tip + (mv.to.tip - mv.from.tip) * t0;
      const Vec3 p1 = mv.from.tip + (mv.to.tip - mv.from.tip) * t1;
      out.emplace_back(cutter, p0, p1, slerp(a0, a1, phi, 0.5 * (t0 + t1)));
    }
  }
  return out;
}

}  // namespace scallop
