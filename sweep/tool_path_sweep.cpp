#include "sweep/tool_path_sweep.h"

#include <cmath>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"

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
  const CutterTeeth &ta = c.teeth, &tb = cutter.teeth;
  if (ta.flutes != tb.flutes || ta.helixDeg != tb.helixDeg || ta.runout != tb.runout ||
      ta.runoutPhaseDeg != tb.runoutPhaseDeg)
    return false;
  const Vec3 da = a.end() - a.start(), db = bEnd - bStart;
  const double la = length(da), lb = length(db);
  if (la == 0 || lb == 0) return la == 0 && lb == 0 ? false : true;
  return length(cross(da, db)) <= 1e-12 * la * lb && dot(da, db) > 0;
}

}  // namespace

std::vector<SweptMove> sweepToolPath(const std::vector<Cutter>& cutters, const ToolPath& path,
                                     const CuttingModel& cutting) {
  std::vector<SweptMove> out;
  // Teeth: the spindle angle at the start of each entry of `out` and its rate, rad per
  // mm of the tip's path: phi(s) = phi0 + 2 pi s / (flutes fz), s along every move
  // (rapids too) in file order. fmod by 2 pi is exact, and keeps phi small.
  struct Spindle {
    double phaseStart, radPerMm;
    uint16_t tool;
  };
  std::vector<Spindle> spindle;
  const bool teeth = cutting.teeth();
  double phase = std::fmod(cutting.phaseDeg * kPi / 180, 2 * kPi);
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& mv = path.moves[k];
    const std::string where = "path move " + std::to_string(k + 1);
    double radPerMm = 0;
    if (teeth && mv.tool < cutters.size()) {
      const double fz = mv.feedPerTooth > 0 ? mv.feedPerTooth : cutting.feedPerTooth;
      if (fz > 0) radPerMm = 2 * kPi / (cutters[mv.tool].teeth.flutes * fz);
    }
    const double phaseStart = phase;
    phase = std::fmod(phase + radPerMm * length(mv.to.tip - mv.from.tip), 2 * kPi);
    if (mv.rapid) continue;
    if (mv.tool >= cutters.size())
      throw InputError(where, "tool index " + std::to_string(mv.tool) + " has no cutter (" +
                                  std::to_string(cutters.size()) + " given)");
    if (teeth && !(radPerMm > 0))
      throw InputError(where,
                       "the teeth cutting model needs a feed per tooth: set "
                       "cutting.feed_per_tooth in the job (or F and S in the program)");
    if (teeth && cutters[mv.tool].general())
      throw InputError(where, std::string("the teeth cutting model supports ball, flat and bull "
                                          "cutters; tool ") +
                                  std::to_string(mv.tool) + " is a " +
                                  toString(cutters[mv.tool].type) +
                                  " cutter (use the envelope model)");
    const Cutter cutter = teeth ? cutters[mv.tool].spindleEnvelope() : cutters[mv.tool];
    const PoseCurve curve = PoseCurve::ofMove(path, mv, where.c_str());
    if (teeth && !curve.linearTip())
      throw InputError(where,
                       "the teeth cutting model needs a straight tip motion; TCP-off machine "
                       "moves (G49) are not supported with teeth");
    // A general cutter sweeps every move through SweptMove's certified search.
    if (curve.constantAxis() && !cutter.general()) {
      const Vec3 axis = curve.axis(0);
      if (!out.empty() && continues(out.back(), curve.tipStart(), curve.tipEnd(), axis, cutter) &&
          (!teeth || spindle.back().radPerMm == radPerMm)) {
        // Keep a zero-length predecessor's position out of the merged move.
        const Vec3 start = out.back().start();
        const bool restart = length(out.back().end() - start) == 0;
        const Vec3 from = restart ? curve.tipStart() : start;
        out.back() = SweptMove(SweptSegment(cutter, from, curve.tipEnd(), axis));
        if (teeth && restart) spindle.back().phaseStart = phaseStart;
        continue;
      }
      out.emplace_back(SweptSegment(cutter, curve.tipStart(), curve.tipEnd(), axis));
    } else {
      out.emplace_back(cutter, curve);
    }
    spindle.push_back({phaseStart, radPerMm, mv.tool});
  }
  if (teeth) {
    // Each move's edges: the cutter with its teeth (the move holds its spindle
    // envelope), phi(t) = phaseStart + radPerMm |tip1 - tip0| t.
    size_t i = 0;
    for (SweptMove& m : out) {
      const Spindle& sp = spindle[i++];
      const double len = length(m.end() - m.start());
      m.attachTeeth(std::make_shared<ToothSweep>(cutters[sp.tool], m.curve(), sp.phaseStart,
                                                 sp.radPerMm * len));
    }
  }
  return out;
}

std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                     const CuttingModel& cutting) {
  if (!path.cutters.empty()) return sweepToolPath(path.cutters, path, cutting);
  return sweepToolPath(std::vector<Cutter>{cutter}, path, cutting);
}

}  // namespace scallop
