#include "tools/io/move_window.h"

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "sweep/pose_curve.h"

namespace scallop {

namespace {

double lean(const Vec3& axis) {
  const double l = length(axis);
  return l > 0 ? std::hypot(axis.x, axis.y) / l : 1.0;
}

bool near(const Vec3& a, const Vec3& b, double tolerance) {
  return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance &&
         std::fabs(a.z - b.z) <= tolerance;
}

bool far(const Vec3& p) {
  return std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))) > kMaxMagnitudeMm;
}

// A straight cutting move with one axis: what the sweep may merge with its neighbours.
bool mergeable(const Move& mv) {
  return !mv.rapid && mv.arc == 0 && mv.rotary == 0 && near(mv.from.axis, mv.to.axis, 1e-9);
}

}  // namespace

MoveWindowFilter::MoveWindowFilter(const ReadWindow& window)
    : w_(window),
      teeth_(window.cutting.teeth()),
      phase_(std::fmod(degToRad(window.cutting.phaseDeg), 2 * kPi)) {}

// The sweep's rate of the spindle's angle along the tip's path (tool_path_sweep.cpp).
double MoveWindowFilter::radiansPerMm(const ToolPath& path, const Move& mv) const {
  const int flutes = w_.oneToolFlutes > 0                ? w_.oneToolFlutes
                     : mv.tool < path.cutters.size()     ? path.cutters[mv.tool].teeth.flutes
                                                         : 0;
  const double fz = mv.feedPerTooth > 0 ? mv.feedPerTooth : w_.cutting.feedPerTooth;
  return flutes > 0 && fz > 0 ? 2 * kPi / (flutes * fz) : 0.0;
}

bool MoveWindowFilter::meets(const ToolPath& path, const Move& mv, bool& forced) const {
  // Kept whatever their place: what the checks after reading must see.
  forced = far(mv.from.tip) || far(mv.to.tip) ||
           (mv.rotary > 0 && (mv.rotary > path.rotary.size() || !path.rotary[mv.rotary - 1].tcp)) ||
           (mv.arc > path.arcs.size()) || (teeth_ && !mv.rapid && !(radiansPerMm(path, mv) > 0));
  if (forced) return true;
  Box3 tip;
  tip.extend(mv.from.tip);
  tip.extend(mv.to.tip);
  if (mv.arc > 0) {
    const Box3 arc = path.arcs[mv.arc - 1].bounds();
    tip.extend(arc.min);
    tip.extend(arc.max);
  }
  const double tilt = mv.rotary > 0 ? 1.0 : std::max(lean(mv.from.axis), lean(mv.to.axis));
  const double scale = std::fmax(std::fmax(std::fabs(tip.min.x), std::fabs(tip.max.x)),
                                 std::fmax(std::fabs(tip.min.y), std::fabs(tip.max.y)));
  const double reach = w_.radius + w_.fluteLength * tilt + 1e-9 + 1e-12 * scale;
  auto overlaps = [&](double x0, double y0, double x1, double y1) {
    return tip.max.x + reach >= x0 && tip.min.x - reach <= x1 && tip.max.y + reach >= y0 &&
           tip.min.y - reach <= y1;
  };
  if (overlaps(w_.x0, w_.y0, w_.x1, w_.y1)) return true;
  return mv.rapid && overlaps(w_.stock.min.x, w_.stock.min.y, w_.stock.max.x, w_.stock.max.y);
}

// Looser than the sweep's own test in every part, so a group is never split.
bool MoveWindowFilter::continues(const Group& g, const Move& mv) const {
  if (!g.mergeable || !mergeable(mv) || !near(g.axis, mv.from.axis, 1e-9)) return false;
  const double scale = 1 + std::fmax(std::fabs(g.to.x), std::fmax(std::fabs(g.to.y), std::fabs(g.to.z)));
  if (!near(g.to, mv.from.tip, 1e-9 * scale)) return false;
  const Vec3 da = g.to - g.from, db = mv.to.tip - mv.from.tip;
  const double la = length(da), lb = length(db);
  if (la == 0 || lb == 0) return true;
  return length(cross(da, db)) <= 1e-9 * la * lb && dot(da, db) > -1e-9 * la * lb;
}

void MoveWindowFilter::decide(Group& g, bool keep) {
  for (size_t i = g.first; i < g.end; ++i)
    if (pending_[i].cutting) pending_[i].keep = keep;
  if (keep) {
    lastKept_ = true;
    lastKeptMergeable_ = g.mergeable;
    lastKeptTo_ = g.to;
    lastKeptAxis_ = g.axis;
  }
}

void MoveWindowFilter::compact(ToolPath& path, std::vector<int64_t>& lines, size_t finalEnd) {
  if (finalEnd == 0) return;
  size_t write = base_;
  for (size_t i = 0; i < finalEnd; ++i) {
    const size_t k = base_ + i;
    if (!pending_[i].keep) {
      ++leftOut_;
      previousLeftOut_ = true;
      continue;
    }
    if (teeth_ && previousLeftOut_) path.phaseMarks.push_back({write, pending_[i].phase});
    previousLeftOut_ = false;
    path.moves[write] = path.moves[k];
    lines[write] = lines[k];
    ++write, ++kept_;
  }
  // The moves not yet settled follow the kept ones.
  const size_t gone = base_ + finalEnd - write;
  if (gone > 0) {
    std::move(path.moves.begin() + std::ptrdiff_t(base_ + finalEnd), path.moves.end(),
              path.moves.begin() + std::ptrdiff_t(write));
    std::move(lines.begin() + std::ptrdiff_t(base_ + finalEnd), lines.end(),
              lines.begin() + std::ptrdiff_t(write));
    path.moves.resize(path.moves.size() - gone);
    lines.resize(lines.size() - gone);
  }
  pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(finalEnd));
  base_ = write;
  for (Group* g : {&open_, &held_})
    if (g->open) g->first -= finalEnd, g->end -= finalEnd;
}

void MoveWindowFilter::judgeLast(ToolPath& path, std::vector<int64_t>& lines) {
  const size_t k = path.moves.size() - 1;
  const Move& mv = path.moves[k];
  ++read_;
  if (!mv.rapid) {
    if (toolMoves_.size() <= mv.tool) toolMoves_.resize(size_t(mv.tool) + 1);
    ToolMoves& t = toolMoves_[mv.tool];
    if (t.count++ == 0) t.firstLine = lines[k];
    t.lastLine = lines[k];
  }
  Judged j;
  j.cutting = !mv.rapid;
  j.phase = phase_;
  if (teeth_) {
    // As the sweep advances it: along every move, rapids too, an arc by its length.
    const double pathMm = mv.arc > 0 && mv.arc <= path.arcs.size()
                              ? PoseCurve::ofMove(path, mv).pathLength()
                              : length(mv.to.tip - mv.from.tip);
    phase_ = std::fmod(phase_ + radiansPerMm(path, mv) * pathMm, 2 * kPi);
  }
  bool forced = false;
  const bool reaches = meets(path, mv, forced);
  pending_.push_back(j);
  const size_t at = pending_.size() - 1;
  if (mv.rapid) {
    pending_[at].keep = reaches;  // the sweep skips rapids: no group
  } else if (open_.open && continues(open_, mv)) {
    if (length(open_.to - open_.from) == 0) open_.from = mv.from.tip;
    open_.to = mv.to.tip;
    open_.meets = open_.meets || reaches;
    open_.end = at + 1;
  } else {
    // A new group: the open one is decided, and a group left out before it is kept
    // after all when the sweep could merge this move onto the last group kept.
    if (open_.open) {
      decide(open_, open_.meets);
      if (!open_.meets) held_ = open_;
      open_.open = false;
    }
    if (held_.open) {
      Group last;
      last.mergeable = lastKeptMergeable_, last.to = lastKeptTo_, last.axis = lastKeptAxis_;
      last.from = lastKeptTo_;  // its direction is unknown here: any direction continues
      if (lastKept_ && continues(last, mv)) decide(held_, true);
      held_.open = false;
    }
    compact(path, lines, at);
    open_.open = true;
    open_.mergeable = mergeable(mv);
    open_.meets = reaches || forced;
    open_.first = pending_.size() - 1;
    open_.end = open_.first + 1;
    open_.from = mv.from.tip, open_.to = mv.to.tip, open_.axis = mv.from.axis;
    return;
  }
  // Rapids between groups settle at once: compact now and then so they do not pile up.
  if (!open_.open && !held_.open && pending_.size() >= 4096) compact(path, lines, pending_.size());
}

void MoveWindowFilter::finish(ToolPath& path, std::vector<int64_t>& lines) {
  if (path.moves.size() > base_ + pending_.size()) judgeLast(path, lines);
  if (open_.open) {
    decide(open_, open_.meets);
    open_.open = false;
  }
  held_.open = false;
  // A program none of whose moves reaches the grid keeps its last move (a path is never
  // empty; the sweep's own window leaves it out).
  if (kept_ == 0 && !pending_.empty() &&
      std::none_of(pending_.begin(), pending_.end(), [](const Judged& j) { return j.keep; }))
    pending_.back().keep = true;
  compact(path, lines, pending_.size());
}

}  // namespace scallop
