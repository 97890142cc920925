#include "sweep/tool_path_sweep.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

// The sweep's entries in the making, members of ToolPathSweeper::State (a named
// namespace: a class with external linkage holds them).
namespace sweep_state {

// One entry of the output before it is built: a turning move (built at once, in path
// order: each takes the next knots identity) or a constant-axis segment, which later
// moves along the same line may still extend.
struct Planned {
  bool turning = false;
  size_t built = 0;  // turning: its index among the turning moves built
  size_t cutter = 0;
  Vec3 from, to, axis;
};

// Teeth: the spindle angle at the start of a planned entry and its rate, rad per mm of
// the tip's path: phi(s) = phi0 + 2 pi s / (flutes fz), s along every move (rapids too)
// in file order. fmod by 2 pi is exact, and keeps phi small.
struct Spindle {
  double phaseStart, radPerMm;
  uint16_t tool;
  bool counterClockwise;
  // A turning CL move's mirror image in y = 0, built as the mirrored job builds it
  // (ToothSweep::Mirror); arcs and machine moves have none. A pointer: the entry of
  // every other move stays small.
  std::unique_ptr<const PoseCurve> mirrored;
};

}  // namespace sweep_state

using sweep_state::Planned;
using sweep_state::Spindle;

namespace {

Vec3 mirrorY(const Vec3& v) {
  return {v.x, -v.y, v.z};
}

// True when the constant-axis entry `a` is continued by the segment (bStart, bEnd) along
// the same line, in the same sense, with the same axis and cutter: then the union of
// their swept solids is the swept solid of the merged segment, so merging is exact.
bool continues(const Planned& a, const Cutter& c, const Vec3& bStart, const Vec3& bEnd,
               const Vec3& axis, const Cutter& cutter) {
  if (a.turning || a.axis != axis || a.to != bStart) return false;
  if (c.type != cutter.type || c.radius != cutter.radius || c.cornerRadius != cutter.cornerRadius ||
      c.fluteLength != cutter.fluteLength || c.profile != cutter.profile)
    return false;
  const CutterTeeth &ta = c.teeth, &tb = cutter.teeth;
  if (ta.flutes != tb.flutes || ta.helixDeg != tb.helixDeg || ta.runout != tb.runout ||
      ta.runoutPhaseDeg != tb.runoutPhaseDeg || ta.toothAnglesDeg() != tb.toothAnglesDeg() ||
      ta.edgeSpans() != tb.edgeSpans() || ta.toothRakes() != tb.toothRakes() ||
      ta.toothOffsets() != tb.toothOffsets())
    return false;
  const Vec3 da = a.to - a.from, db = bEnd - bStart;
  const double la = length(da), lb = length(db);
  if (la == 0 || lb == 0) return la == 0 && lb == 0 ? false : true;
  return length(cross(da, db)) <= 1e-12 * la * lb && dot(da, db) > 0;
}

// The xy box of a constant-axis segment's swept solid, from its ends alone: every point
// of the cutter is tip + s a + rho u with 0 <= s <= L, 0 <= rho <= R and u a unit
// vector at right angles to the unit axis a, so it lies within R + L |a_xy| of the tip
// in x and y. Grown by a rounding margin far above the few roundings made here.
Box3 segmentReach(const Cutter& c, const Vec3& from, const Vec3& to, const Vec3& axis) {
  const double lean = std::hypot(axis.x, axis.y) / length(axis);
  const double scale = std::fmax(std::fmax(std::fabs(from.x), std::fabs(from.y)),
                                 std::fmax(std::fabs(to.x), std::fabs(to.y)));
  const double reach = c.radius + c.fluteLength * lean + 1e-9 + 1e-12 * scale;
  Box3 box;
  box.extend(from);
  box.extend(to);
  box.min.x -= reach, box.min.y -= reach, box.max.x += reach, box.max.y += reach;
  return box;
}

// Entries are built a batch at a time: the constant-axis segments of a batch in parallel
// (each once, with its final ends: a merged segment was rebuilt at every move it took
// in), then appended in path order, with their teeth. With a window, an entry whose box
// misses it is not built (a segment) or not kept (a turning move).
constexpr size_t kBatch = 4096;

}  // namespace

struct ToolPathSweeper::State {
  std::vector<Cutter> cutters;
  std::vector<Cutter> swept;  // the cutter each tool sweeps: with teeth, its spindle envelope
  CuttingModel cutting;
  bool teeth = false;
  std::optional<SweepWindow> window;
  std::vector<SweptMove> out;
  std::vector<Planned> planned;
  std::vector<SweptMove> turning;  // the turning entries of `planned`, built
  std::vector<Spindle> spindle;    // teeth: one a planned entry
  double phase = 0;                // rad, the spindle's at the next move's start
  size_t moves = 0;                // moves added so far (their numbers in messages)

  void build(size_t count);
  void attachTeeth(SweptMove& m, const Spindle& sp) const;
  void add(const ToolPath& path);
};

void ToolPathSweeper::State::build(size_t count) {
  std::vector<std::optional<SweptSegment>> segments(count);
  const SweepWindow* w = window ? &*window : nullptr;
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    const Planned& p = planned[i];
    if (p.turning) return;
    const Cutter& c = swept[p.cutter];
    if (!w || w->meets(segmentReach(c, p.from, p.to, p.axis)))
      segments[i].emplace(c, p.from, p.to, p.axis);
  });
  for (size_t i = 0; i < count; ++i) {
    bool keep = false;
    if (planned[i].turning) {
      SweptMove& m = turning[planned[i].built];
      keep = !w || w->meets(m.bounds());
      if (keep) out.push_back(std::move(m));
    } else if (segments[i]) {
      out.emplace_back(*segments[i]);
      keep = true;
    }
    if (keep && teeth) attachTeeth(out.back(), spindle[i]);
  }
  planned.erase(planned.begin(), planned.begin() + std::ptrdiff_t(count));
  if (teeth) spindle.erase(spindle.begin(), spindle.begin() + std::ptrdiff_t(count));
  if (planned.empty() || !planned.front().turning) turning.clear();
}

// A move's edges: the cutter with its teeth (the move holds its spindle envelope),
// phi(t) = phaseStart + radPerMm len t, len the tip's path length (an arc's: its speed is
// constant, so phi is linear in the distance along it too). A lowered envelope's move is
// raised back to the spindle's tip.
void ToolPathSweeper::State::attachTeeth(SweptMove& m, const Spindle& sp) const {
  const double len = m.curve().pathLength();
  const Cutter& cutter = cutters[sp.tool];
  const double drop = cutter.teeth.axialReach();
  auto raised = [drop](const PoseCurve& curve) {
    if (!(drop > 0)) return curve;
    const Vec3 axis = curve.axis(0), raise = drop * axis;
    return PoseCurve::linear({curve.tipStart() + raise, axis}, {curve.tipEnd() + raise, axis});
  };
  // A CCW move is computed on its mirror image, as the mirrored job computes it.
  std::optional<ToothSweep::Mirror> mirror;
  if (sp.counterClockwise && m.segment()) {
    const SweptSegment& seg = *m.segment();
    const auto envelope = std::make_shared<const SweptSegment>(
        swept[sp.tool], mirrorY(seg.start()), mirrorY(seg.end()), mirrorY(seg.axis()));
    mirror = ToothSweep::Mirror{raised(PoseCurve::linear({envelope->start(), envelope->axis()},
                                                         {envelope->end(), envelope->axis()})),
                                envelope};
  } else if (sp.counterClockwise && sp.mirrored) {
    mirror = ToothSweep::Mirror{*sp.mirrored, nullptr};
  }
  m.attachTeeth(std::make_shared<ToothSweep>(cutter, raised(m.curve()), sp.phaseStart,
                                             sp.radPerMm * len, sp.counterClockwise,
                                             mirror ? &*mirror : nullptr));
}

void ToolPathSweeper::State::add(const ToolPath& path) {
  size_t mark = 0;
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& mv = path.moves[k];
    if (mark < path.phaseMarks.size() && path.phaseMarks[mark].move == k)
      phase = path.phaseMarks[mark++].phase;  // moves before this one were left out
    const size_t number = ++moves;
    double radPerMm = 0;
    if (teeth && mv.tool < cutters.size()) {
      const double fz = mv.feedPerTooth > 0 ? mv.feedPerTooth : cutting.feedPerTooth;
      if (fz > 0) radPerMm = 2 * kPi / (cutters[mv.tool].teeth.flutes * fz);
    }
    const double phaseStart = phase;
    // s runs along the tip's path: an arc's length, not its chord.
    const double pathMm = mv.arc > 0 && mv.arc <= path.arcs.size()
                              ? PoseCurve::ofMove(path, mv).pathLength()
                              : length(mv.to.tip - mv.from.tip);
    phase = std::fmod(phase + radPerMm * pathMm, 2 * kPi);
    if (mv.rapid) continue;
    const std::string where = "path move " + std::to_string(number);
    if (mv.tool >= cutters.size())
      throw InputError(where, "tool index " + std::to_string(mv.tool) + " has no cutter (" +
                                  std::to_string(cutters.size()) + " given)");
    if (teeth && !(radPerMm > 0))
      throw InputError(where,
                       "the teeth cutting model needs a feed per tooth: set "
                       "cutting.feed_per_tooth in the job (or F and S in the program)");
    const bool ccw = mv.spindle != 0 ? mv.spindle < 0 : cutting.counterClockwise;
    const Cutter& cutter = swept[mv.tool];
    PoseCurve curve = PoseCurve::ofMove(path, mv, where.c_str());
    if (teeth && !curve.linearTip() && !curve.arcTip())
      throw InputError(where,
                       "the teeth cutting model needs a straight tip motion; TCP-off machine "
                       "moves (G49) are not supported with teeth");
    // Teeth reaching below the tip: the envelope is swept that much lower (a straight
    // move with a constant axis: lowering it is a translation).
    const double drop = teeth ? cutters[mv.tool].teeth.axialReach() : 0;
    if (drop > 0) {
      if (!curve.constantAxis() || !curve.linearTip())
        throw InputError(where, "tool " + std::to_string(mv.tool) +
                                    " has a tooth reaching below its tip (tooth_offsets: "
                                    "axial > 0), which needs straight moves with a constant "
                                    "tool axis; this move turns the axis or is an arc");
      const Vec3 lower = drop * curve.axis(0);
      curve = PoseCurve::linear({mv.from.tip - lower, mv.from.axis},
                                {mv.to.tip - lower, mv.to.axis}, where.c_str());
    }
    // A general cutter sweeps every move through SweptMove's certified search, and an
    // arc is never merged: it is no segment (its tip is curved).
    if (curve.constantAxis() && curve.linearTip() && !cutter.general()) {
      const Vec3 axis = curve.axis(0);
      if (!planned.empty() &&
          continues(planned.back(), swept[planned.back().cutter], curve.tipStart(), curve.tipEnd(),
                    axis, cutter) &&
          (!teeth ||
           (spindle.back().radPerMm == radPerMm && spindle.back().counterClockwise == ccw))) {
        // Keep a zero-length predecessor's position out of the merged move.
        Planned& back = planned.back();
        const bool restart = length(back.to - back.from) == 0;
        if (restart) back.from = curve.tipStart();
        back.to = curve.tipEnd();
        if (teeth && restart) spindle.back().phaseStart = phaseStart;
        continue;
      }
      if (planned.size() > kBatch) build(planned.size() - 1);
      Planned p;
      p.cutter = mv.tool, p.from = curve.tipStart(), p.to = curve.tipEnd(), p.axis = axis;
      planned.push_back(p);
    } else {
      if (planned.size() > kBatch) build(planned.size());
      Planned p;
      p.turning = true, p.built = turning.size(), p.cutter = mv.tool;
      turning.emplace_back(cutter, curve);
      planned.push_back(p);
    }
    if (!teeth) continue;  // the spindle's entries serve the teeth only
    spindle.push_back({phaseStart, radPerMm, mv.tool, ccw, nullptr});
    if (ccw && !curve.constantAxis() && mv.rotary == 0 && mv.arc == 0)
      spindle.back().mirrored = std::make_unique<const PoseCurve>(
          PoseCurve::linear({mirrorY(mv.from.tip), mirrorY(mv.from.axis)},
                            {mirrorY(mv.to.tip), mirrorY(mv.to.axis)}));
  }
}

ToolPathSweeper::ToolPathSweeper(std::vector<Cutter> cutters, const CuttingModel& cutting,
                                 const SweepWindow* window, size_t cuttingMoves)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.cutters = std::move(cutters);
  s.cutting = cutting;
  s.teeth = cutting.teeth();
  for (const Cutter& c : s.cutters) s.swept.push_back(s.teeth ? c.spindleEnvelope() : c);
  if (window) s.window = *window;
  s.phase = std::fmod(degToRad(cutting.phaseDeg), 2 * kPi);
  // Room for every entry at once, so the moves are never copied as the vector grows.
  // Merged moves leave the end of the room untouched, so never resident (the peak is the
  // same as growing by doubling, which glibc's mremap does without copies: B9 --area 40,
  // 355.1 MB either way).
  s.out.reserve(cuttingMoves);
}

ToolPathSweeper::~ToolPathSweeper() = default;

void ToolPathSweeper::add(const ToolPath& part) {
  state_->add(part);
}

std::vector<SweptMove> ToolPathSweeper::finish() {
  state_->build(state_->planned.size());
  return std::move(state_->out);
}

std::vector<SweptMove> sweepToolPath(const std::vector<Cutter>& cutters, const ToolPath& path,
                                     const CuttingModel& cutting, const SweepWindow* window) {
  ToolPathSweeper sweeper(cutters, cutting, window, path.cuttingMoves());
  sweeper.add(path);
  return sweeper.finish();
}

std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                     const CuttingModel& cutting, const SweepWindow* window) {
  if (!path.cutters.empty()) return sweepToolPath(path.cutters, path, cutting, window);
  return sweepToolPath(std::vector<Cutter>{cutter}, path, cutting, window);
}

}  // namespace scallop
