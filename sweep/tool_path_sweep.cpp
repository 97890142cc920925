#include "sweep/tool_path_sweep.h"

#include <cmath>
#include <string>

#include "sweep/input_error.h"

namespace scallop {

namespace {

// True when the constant-axis move `a` is continued by the segment (bStart, bEnd) along
// the same line, in the same sense, with the same axis and cutter: then the union of
// their swept solids is the swept solid of the merged segment, so merging is exact.
bool continues(const SweptMove& a, const Vec3& bStart, const Vec3& bEnd, const Vec3& axis,
               const Cutter& cutter) {
  if (a.turning() || a.segment()->axis() != axis || a.end() != bStart) return false;
  const Cutter& c = a.cutter();
  if (c.type != cutter.type || c.radius != cutter.radius || c.cornerRadius != cutter.cornerRadius ||
      c.fluteLength != cutter.fluteLength)
    return false;
  const Vec3 da = a.end() - a.start(), db = bEnd - bStart;
  const double la = length(da), lb = length(db);
  if (la == 0 || lb == 0) return la == 0 && lb == 0 ? false : true;
  return length(cross(da, db)) <= 1e-12 * la * lb && dot(da, db) > 0;
}

}  // namespace

std::vector<SweptMove> sweepToolPath(const std::vector<Cutter>& cutters, const ToolPath& path) {
  std::vector<SweptMove> out;
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& mv = path.moves[k];
    if (mv.rapid) continue;
    const std::string where = "path move " + std::to_string(k + 1);
    if (mv.tool >= cutters.size())
      throw InputError(where, "tool index " + std::to_string(mv.tool) + " has no cutter (" +
                                  std::to_string(cutters.size()) + " given)");
    const Cutter& cutter = cutters[mv.tool];
    const PoseCurve curve = PoseCurve::ofMove(path, mv, where.c_str());
    if (curve.constantAxis()) {
      const Vec3 axis = curve.axis(0);
      if (!out.empty() && continues(out.back(), curve.tipStart(), curve.tipEnd(), axis, cutter)) {
        // Keep a zero-length predecessor's position out of the merged move.
        const Vec3 start = out.back().start();
        const Vec3 from = length(out.back().end() - start) == 0 ? curve.tipStart() : start;
        out.back() = SweptMove(SweptSegment(cutter, from, curve.tipEnd(), axis));
        continue;
      }
      out.emplace_back(SweptSegment(cutter, curve.tipStart(), curve.tipEnd(), axis));
      continue;
    }
    out.emplace_back(cutter, curve);
  }
  return out;
}

std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path) {
  if (!path.cutters.empty()) return sweepToolPath(path.cutters, path);
  return sweepToolPath(std::vector<Cutter>{cutter}, path);
}

}  // namespace scallop
