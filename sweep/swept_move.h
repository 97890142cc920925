// SweptMove: the solid swept by a cutter along one move, whatever its axis does, and
// its exact lowest point on a vertical line. One primitive per move of a tool path.
//
// A move whose axis is constant is a SweptSegment (the convex Minkowski sweep,
// swept_segment.cpp; for a cutter of any profile, Kelley's method on the convex f(t) of
// profile_sweep.h, the certified search where it cannot close); a move whose axis turns (CL data
// with a new axis at every point, a 5-axis machine's rotary motion) by the rim and face contacts
// and ray clearance of swept_move.cpp, or the certified search over t (certified_search.h). Either
// way the height is the lowest point of the true swept solid, with a proven lower bound within 1e-9
// mm of the height returned.
//
// Memory: sizeof(SweptMove) bytes per move (424), plus, for a constant-axis
// move, one SweptSegment on the heap (1 024 bytes; see bytesPerMove()).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_segment.h"
#include "sweep/tip_ball.h"
#include "sweep/tooth_sweep.h"

namespace scallop {

class SweptMove {
 public:
  SweptMove(const Cutter& cutter, const PoseCurve& curve);
  // A constant-axis move from an existing segment (the sweep of merged collinear moves).
  explicit SweptMove(const SweptSegment& segment);

  // Gives the move its cutting edges: lowestPoint() then returns the lowest crossing of
  // an edge (ToothSweep), above the envelope's height, which stays the bound the
  // culling uses (support(), bounds(), planeHint()).
  void attachTeeth(std::shared_ptr<const ToothSweep> teeth) { teeth_ = std::move(teeth); }
  const ToothSweep* teeth() const { return teeth_.get(); }
  // The lowest point of the envelope alone (the swept solid), teeth or not.
  LowestPoint envelopeLowestPoint(double x, double y, SectionMemo* memo = nullptr,
                                  double cutoff = HUGE_VAL, double cutoffAnchor = NAN) const;

  // The lowest point of the swept solid on the vertical line through (x, y) (with teeth:
  // the lowest point an edge passes through, ToothSweep::lowestCrossing). `memo`
  // serves the moves that takesSectionMemo() (SweptSegment::lowestPoint). A height at or above
  // `cutoff` may be reported as a miss; the height returned otherwise does not depend
  // on `cutoff`, `memo` or `cutoffAnchor`: the t in [0, 1] a turning move first tries
  // to prove it stays above the cutoff from (swept_move.cpp step 4a; NaN: the knots').
  LowestPoint lowestPoint(double x, double y, SectionMemo* memo = nullptr, double cutoff = HUGE_VAL,
                          double cutoffAnchor = NAN) const;

  // True only if the solid provably stays above z on every vertical line within
  // `radius` mm of (x, y) (a turning move's ray clearance from its middle, for a disc of
  // lines: ray_clearance.h); false proves nothing (and constant-axis moves always say so).
  bool clearsAbove(double x, double y, double z, double radius) const;

  // The lowest point of the cutter standing at pose(t) alone: a convex function of
  // (x, y) (K(t) is convex) at or above the swept solid's heights.
  LowestPoint stationaryLowestPoint(double t, double x, double y) const;

  // A lowest point whose normal makes a good culling plane through support() near
  // (x, y) (any normal gives a valid one): the exact lowest point for a constant axis,
  // the cutter at mid-move for a turning move, which costs one stationary evaluation
  // instead of a search.
  LowestPoint planeHint(double x, double y) const;
  // A closer one for the same use, for about a third of what an exact evaluation costs
  // at a fresh place (no knots, no proof): for a turning move, where the rim contact is
  // located from pose tStart (rim_contact.h; the middle, or where a nearby line touched),
  // its point and normal, unproven (a plane needs none); elsewhere planeHint().
  LowestPoint locatedPlaneHint(double x, double y, double tStart = 0.5) const;

  // An upper bound of the swept solid's support function max over the solid of
  // dot(dir, p) (exact for a constant axis). For dir.z < 0 the plane dot(dir, p) =
  // support(dir) lies below every height: the scene's culling planes.
  double support(const Vec3& dir) const;
  // Axis-aligned bounds containing the swept solid (from support() in the six
  // directions, so tight for a constant axis and within the turn's bound otherwise).
  Box3 bounds() const;

  const Cutter& cutter() const { return cutter_; }
  const PoseCurve& curve() const { return curve_; }
  const Vec3& start() const { return curve_.tipStart(); }  // tip at t = 0
  const Vec3& end() const { return curve_.tipEnd(); }      // tip at t = 1
  bool turning() const { return !segment_; }
  // True where lowestPoint() runs a constant-axis kernel, which a SectionMemo serves and
  // a cutoff prunes in closed form: the move's SweptSegment, or a general cutter's tip
  // ball (tip_ball.h) on a constant axis and a linear tip, whose hemisphere's sweep is a
  // SweptSegment. The scene then keeps its memos and its neighbours' cutoffs as for a
  // constant-axis move (scene_tiles.h), though the move is turning() (no segment).
  bool takesSectionMemo() const {
    return segment_ || (tipBall_ && curve_.constantAxis() && curve_.linearTip());
  }
  // The spacing (mm) of the knots a turning move starts its contact search from
  // (contact_knots.h; default kContactKnotSpacing; 0: none, start from the middle).
  // Heights differ only within the proof gap from one spacing to another, but are a
  // function of (move, spacing, x, y).
  void setContactKnotSpacing(double mm);
  double contactKnotSpacing() const { return knotSpacing_; }
  // The constant-axis kernel, or null for a turning move.
  const SweptSegment* segment() const { return segment_.get(); }

  // Bytes a move of this kind holds (the object and what it owns), for memory
  // estimates made before a scene is built; `tipBall`: a general cutter with a ball
  // tip (tip_ball.h), which holds the hemisphere's move too; `ccwTeeth`: teeth turning
  // counter-clockwise, whose constant-axis move holds its mirror image's segment too.
  static size_t bytesPerMove(bool turning, bool teeth = false, bool tipBall = false,
                             bool ccwTeeth = false);
  bool hasTipBall() const { return tipBall_ != nullptr; }

  // Searches of turning moves, over all threads so far, that ran out of samples before
  // their proof closed (their height is still a real point of the solid). Tests
  // expect none.
  static unsigned long long unprovenSearches();
  // The same, made by the calling thread (raycast/zmap_caster.cpp counts a run's).
  static unsigned long long unprovenSearchesOnThisThread();

 private:
  LowestPoint turningLowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                 double cutoffAnchor) const;
  // envelopeLowestPoint's body, forced inline into lowestPoint (swept_move.cpp).
  LowestPoint envelopeOf(double x, double y, SectionMemo* memo, double cutoff,
                         double cutoffAnchor) const;
  // A general cutter with a ball tip (tip_ball.h) on a linear tip: the hemisphere's
  // sweep, and the lowest the rest of the cutter can reach over the move, mm.
  struct TipBallMove;
  void makeTipBall();
  LowestPoint tipBallLowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                 double cutoffAnchor) const;

  Cutter cutter_;
  PoseCurve curve_;
  std::shared_ptr<const SweptSegment> segment_;  // constant axis only
  std::shared_ptr<const ToothSweep> teeth_;      // the "teeth" cutting model only
  std::shared_ptr<const TipBallMove> tipBall_;   // general cutters with a ball tip only
  double reach_ = 0;      // farthest cutter point from the tip, hypot(L, R), mm
  double zTop_ = 0;       // turning: an upper bound of the solid's highest z, mm
  double tipSpeed_ = 0;   // turning: >= |d tip / dt| over the move, mm per unit t
  uint64_t knotsId_ = 0;  // turning: its rim-contact knots' identity (contact_knots.h)
  double knotSpacing_;    // mm, the knots' lattice spacing
};

}  // namespace scallop
