// The lowest point of the solid swept by a cutter whose axis turns during the move.
//
// Notation: pose(t) = (tip(t), axis(t)), t in [0, 1], from a PoseCurve (tip linear,
// the cutter turned rigidly about its tip with angular velocity Omega(t), |Omega| <=
// omega: pose_curve.h). K(t) is the cutter at pose(t), convex. The swept solid
// S = U_t K(t) is not convex; its lowest point on the vertical line l through q = (x, y)
// is
//     F = min over t of f(t),   f(t) = the lowest point of K(t) on l (+inf: a miss),
// where each f(t) is exact (cutterLowestPoint, swept_segment.cpp). F is found with a
// proof: a height U attained by the solid and a proven lower bound within 1e-9 mm of it.
//
//   1.-3. and 5. The certified search (certified_search.cpp): every f(t) evaluated is a
//      real height, so the smallest, U, is >= F; proven lower bounds of f over
//      intervals of t (interval_bounds.cpp: planes fixed to the world or to the cutter,
//      a grown cutter, a Taylor form) are split best first until they reach
//      U - 1e-9 mm, after the minimum of f is located and, where it can, proven at once.
//   4. Ray clearance (ray_clearance.cpp): seen from the cutter, the point Q = (x, y, z)
//      moves along a curve within omega^2 D + 2 omega |p1 - p0| (times tau^2 / 2) of its
//      tangent line, and the distance from that line to the cutter's convex core is
//      convex in t, so a ladder of tangent lines proves the downward ray from Q misses
//      every K(t) in a few closed-form distances, without any stationary search.
//   4a. Before anything is sampled, with z = the cutoff: a move that provably stays
//      above it is a miss (on B3, 45 % of the moves a cell asks about). The scene asks
//      a guessed winner (a neighbour's) without a cutoff, since a winner always fails it.
//   4b. Once the best sample's slope is small (|f'| <= 1e-6) or nothing brackets a
//      minimum, with z = U - 1e-9 and the best sample as the anchor: the whole move is
//      proven at once, in place of step 3's ladder of intervals (B3: 99.99 % of the
//      searches that reach it). After step 5's located minimum, where it fails, the
//      Taylor form 2d from the best sample over the whole of [0, 1]: on a flat bottom
//      face g curves away from the line only through f'' (the turn), which tangent lines
//      cannot see. Where both fail, step 3 goes on as before.
//   6. The rim contact: where the cutter meets l on its corner, the lowest point is the
//      minimum over (t, phi) of the balls round C's rim, located by Newton's method
//      (rim_contact.cpp) from the contact blended from fixed knots (contact_knots.cpp)
//      and proven by step 4b from its t: on CAM paths ~1.2 evaluations of a closed form
//      and one proof, no stationary search.
//   7. The face contact: where the cutter meets l on its flat bottom face, Newton's
//      method on the crossing of l with the tip plane over t, proven by the Taylor form
//      of that plane over the whole move (face_contact.cpp): no stationary search.
//   The order: 4a anchored where the caller says (a same-pass neighbour of the cell's
//   best move: the pose they share), else at t = 1/2 and then at the knots' t; 7 first
//   where the knots found no rim contact; 6; 7; then 5 and 3 from scratch.
//   The search's order depends on (x, y) alone (the cutoff only stops it, step 4a only
//   returns a miss, and the knots are a function of the move), so the height returned is
//   the same whatever was evaluated before, on any thread.
#include "sweep/swept_move.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sweep/certified_search.h"
#include "sweep/contact_knots.h"
#include "sweep/face_contact.h"
#include "sweep/profile_sweep.h"
#include "sweep/ray_clearance.h"
#include "sweep/rim_contact.h"

namespace scallop {

namespace {
// rad per unit t: moves that turn less try step 4a's proof from the expected contact only.
constexpr double kHalvesTurn = 0.05;
// Contact normals flatter than this (|n.z|) give the rest's plane too steep a slope to
// settle anything: the general path decides there.
constexpr double kTipBallMinNormalZ = 0.05;
// Section memos of tip balls on a constant axis, per thread, for callers that give none
// (the scene gives its own: takesSectionMemo). A memo is used only for its own segment
// and section, so heights do not depend on which slot a move takes.
constexpr int kTipBallMemos = 8;
}  // namespace

struct SweptMove::TipBallMove {
  SweptMove move;  // the hemisphere swept along the same curve
  SweptRest rest;  // the rest of the cutter over the move
};

void SweptMove::makeTipBall() {
  const TipBall ball = tipBallOf(cutter_);
  if (!ball.valid || !curve_.linearTip()) return;
  tipBall_ = std::make_shared<const TipBallMove>(
      TipBallMove{SweptMove(tipBallCutter(ball), curve_), SweptRest(cutter_, ball, curve_)});
}

LowestPoint SweptMove::tipBallLowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                          double cutoffAnchor) const {
  const SweptMove& ball = tipBall_->move;
  if (ball.turning()) {
    memo = nullptr;
  } else if (!memo) {
    thread_local SectionMemo memos[kTipBallMemos];
    memo = &memos[(reinterpret_cast<uintptr_t>(this) / sizeof(SweptMove)) % kTipBallMemos];
  }
  return ball.envelopeLowestPoint(x, y, memo, cutoff, cutoffAnchor);
}

SweptMove::SweptMove(const Cutter& cutter, const PoseCurve& curve)
    : cutter_(cutter),
      curve_(curve),
      reach_(std::hypot(cutter.fluteLength, cutter.radius)),
      knotSpacing_(kContactKnotSpacing) {
  // A curved tip (an arc) goes through the turning kernel even with a constant axis
  // (SweptSegment is the sweep along a straight line only), and so does a general cutter.
  if (curve_.constantAxis() && curve_.linearTip() && !cutter.general())
    segment_ = std::make_shared<const SweptSegment>(cutter, curve_.tipStart(), curve_.tipEnd(),
                                                    curve_.axis(0));
  else
    tipSpeed_ = curve_.tipSpeedBound(), zTop_ = support({0, 0, 1}), knotsId_ = newContactKnotsId();
  if (cutter.general()) makeTipBall();
}

SweptMove::SweptMove(const SweptSegment& segment)
    : cutter_(segment.cutter()),
      curve_(PoseCurve::linear({segment.start(), segment.axis()}, {segment.end(), segment.axis()})),
      reach_(std::hypot(segment.cutter().fluteLength, segment.cutter().radius)),
      knotSpacing_(kContactKnotSpacing) {
  // SweptSegment's closed-form sweep knows the cutter only by radius and corner radius
  // (ball, flat, bull): a cutter of any profile in it would be swept as the flat
  // cylinder of its largest width, below the true solid wherever the profile is
  // narrower (a barrel at tilt 88.5 deg: 0.30 mm under its floor). Such a cutter goes
  // through the certified search like the constructor above sends it.
  if (!cutter_.general())
    segment_ = std::make_shared<const SweptSegment>(segment);
  else
    tipSpeed_ = curve_.tipSpeedBound(), zTop_ = support({0, 0, 1}), knotsId_ = newContactKnotsId();
  if (cutter_.general()) makeTipBall();
}

void SweptMove::setContactKnotSpacing(double mm) {
  if (!(mm >= 0) || mm == knotSpacing_) return;
  knotSpacing_ = mm;
  // The cached knots of the old spacing are another move's now.
  if (!segment_) knotsId_ = newContactKnotsId();
}

unsigned long long SweptMove::unprovenSearches() {
  return unprovenCertifiedSearches();
}

unsigned long long SweptMove::unprovenSearchesOnThisThread() {
  return unprovenCertifiedSearchesOnThisThread();
}

size_t SweptMove::bytesPerMove(bool turning, bool teeth, bool tipBall, bool ccwTeeth) {
  // The control block and the segment of a constant-axis move live on the heap, and
  // so do the teeth. A general cutter's constant-axis move has no segment, but its tip
  // ball's move (a ball along the same line) has one: counted as the move's.
  return sizeof(SweptMove) + (turning ? 0 : sizeof(SweptSegment) + 32) +
         (teeth ? sizeof(ToothSweep) + 32 : 0) + (tipBall ? sizeof(TipBallMove) + 32 : 0) +
         (teeth && ccwTeeth && !turning ? sizeof(SweptSegment) + 32 : 0);
}

double SweptMove::support(const Vec3& dir) const {
  if (segment_) return segment_->support(dir);
  const double len = length(dir);
  if (!(len > 0)) return 0;
  const double h = turningSupport(cutter_, curve_, {reach_, zTop_, tipSpeed_}, dir / len);
  // Round-off of the few products above, scaled back to dir's length.
  return len * (h + 1e-12 * (1 + std::fabs(h)));
}

Box3 SweptMove::bounds() const {
  if (segment_) return segment_->bounds();
  Box3 box;
  box.min = {-support({-1, 0, 0}), -support({0, -1, 0}), -support({0, 0, -1})};
  box.max = {support({1, 0, 0}), support({0, 1, 0}), support({0, 0, 1})};
  return box;
}

LowestPoint SweptMove::stationaryLowestPoint(double t, double x, double y) const {
  const Vec3 tip = curve_.tip(t);
  LowestPoint lp = cutterLowestPoint(cutter_, curve_.axis(t), x - tip.x, y - tip.y);
  lp.z += tip.z;
  lp.t = t;
  return lp;
}

LowestPoint SweptMove::planeHint(double x, double y) const {
  // A plane needs only a normal of the solid: the tip ball's is one where it is lowest.
  if (tipBall_) return tipBall_->move.planeHint(x, y);
  return segment_ ? segment_->lowestPoint(x, y) : stationaryLowestPoint(0.5, x, y);
}

LowestPoint SweptMove::locatedPlaneHint(double x, double y, double tStart) const {
  if (tipBall_) return tipBall_->move.locatedPlaneHint(x, y, tStart);
  if (segment_ || cutter_.general() || !(cutter_.cornerRadius > 0)) return planeHint(x, y);
  RimStart start;
  start.t = tStart;
  const RimContact rim = locateRimContact(cutter_, curve_, x, y, start);
  if (!rim.found) return planeHint(x, y);
  LowestPoint lp;
  lp.hit = true, lp.z = rim.z, lp.normal = rim.normal, lp.t = rim.t;
  return lp;
}

// Forced inline into lowestPoint, the cast's hot path: where GCC made it a call (when
// the teeth's per-tooth groups grew lowestCrossing's inline body) B1 cast 4.2 %
// more instructions a cell.
__attribute__((always_inline)) inline LowestPoint SweptMove::envelopeOf(double x, double y,
                                                                        SectionMemo* memo,
                                                                        double cutoff,
                                                                        double cutoffAnchor) const {
  if (segment_) return segment_->lowestPoint(x, y, memo, cutoff);
  return turningLowestPoint(x, y, memo, cutoff, cutoffAnchor);
}

LowestPoint SweptMove::envelopeLowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                           double cutoffAnchor) const {
  return envelopeOf(x, y, memo, cutoff, cutoffAnchor);
}

bool SweptMove::clearsAbove(double x, double y, double z, double radius) const {
  if (tipBall_) return tipBall_->rest.floor() > z && tipBall_->move.clearsAbove(x, y, z, radius);
  return turning() && raysClearMove(cutter_, curve_, {x, y, z}, radius);
}

LowestPoint SweptMove::lowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                   double cutoffAnchor) const {
  // With teeth the envelope's height is the proven lower bound the crossing search
  // starts from: a move whose envelope is at or above the cutoff has no crossing below.
  const LowestPoint envelope = envelopeOf(x, y, memo, cutoff, cutoffAnchor);
  if (!teeth_) return envelope;
  return teeth_->lowestCrossing(x, y, envelope, cutoff);
}

LowestPoint SweptMove::turningLowestPoint(double x, double y, SectionMemo* memo, double cutoff,
                                          double cutoffAnchor) const {
  const Cutter& c = cutter_;
  // A general cutter with a ball tip: the hemisphere's height where the rest of the
  // cutter provably stays above it (tip_ball.h), a miss where both stay above the cutoff.
  if (tipBall_) {
    const LowestPoint ball = tipBallLowestPoint(x, y, memo, cutoff, cutoffAnchor);
    const SweptRest& rest = tipBall_->rest;
    if (ball.hit) {
      // The rest's floor over the whole move first (one comparison: on CAM paths the
      // flank starts far above the cusps), then its plane along the contact normal.
      if (rest.floor() > ball.z ||
          (ball.normal.z < -kTipBallMinNormalZ && rest.lowerBound(ball.normal, x, y) > ball.z))
        return ball;
    } else if (cutoff < HUGE_VAL && rest.floor() >= cutoff) {
      return {};
    }
  }
  // A general cutter on a constant-axis move with a linear tip: f is convex, Kelley's
  // method proves the height in a few exact evaluations (profile_sweep.h); where it
  // cannot close, the steps below decide.
  if (c.general() && curve_.constantAxis() && curve_.linearTip()) {
    const ProfileSweepResult fast = profileSweepLowestPoint(
        *c.profile, curve_.axis(0), curve_.tipStart(), curve_.tipEnd(), x, y, cutoff);
    if (fast.decided) return fast.point;
  }
  // Step 4a before anything is looked up: from the caller's anchor (a same-pass
  // neighbour of the best move so far: the pose they share), otherwise from the middle
  // of the move (its axis is kept: no trigonometry; this settles most of the moves far
  // from their contact, and without their knots).
  const bool anchored = cutoff < HUGE_VAL && cutoffAnchor >= 0 && cutoffAnchor <= 1;
  if (cutoff < HUGE_VAL &&
      rayClearsMove(c, curve_, {x, y, cutoff}, anchored ? cutoffAnchor : 0.5, 0, 1))
    return {};
  // Where the rim contact is expected (contact_knots.h): the anchor of step 4a's proof
  // and the start of step 6's Newton.
  const RimStart start = !c.general() && c.cornerRadius > 0
                             ? contactStart(knotsId_, knotSpacing_, c, curve_, x, y)
                             : RimStart{};
  // Step 7: the bottom face (face_contact.h), located and proven in closed form. First
  // where the knots round the line found no rim contact (B3: most face lines), else
  // after the rim contact.
  bool faceTried = false;
  auto face = [&](LowestPoint& out) {
    faceTried = true;
    const FaceContact f = locateFaceContact(c, curve_, x, y);
    if (!f.found) return false;
    if (f.z < cutoff) out.hit = true, out.z = f.z, out.normal = f.normal, out.t = f.t;
    return true;
  };
  LowestPoint out;
  const bool faceContact = !c.general() && c.bottomRadius() > 0;
  if (faceContact && !start.hasDirection && face(out)) return out;
  // Step 4a: a move the ray-clearance proof puts above the cutoff is a miss, found
  // without a single stationary search (ray_clearance.h). Not after the caller's anchor
  // failed: such a neighbour loses by nanometres if at all, and from the knots' anchor
  // the proof closed for 3.5 % of them on B3.
  if (cutoff < HUGE_VAL && !anchored) {
    const Vec3 q{x, y, cutoff};
    // From the expected contact first; where the motion turns much (omega above 0.05
    // rad: the curve's term, omega^2 D, is what fails one tangent line), from each end
    // over its half (the term falls fourfold), unless q lies in the cutter at the anchor.
    // On B3 (0.01 rad a move) the halves settled 162 of ~430 000 moves.
    bool inside = false;
    if (rayClearsMove(c, curve_, q, start.t, 0, 1, &inside) ||
        (!inside && curve_.turnRate() > kHalvesTurn && rayClearsMove(c, curve_, q, 0, 0, 0.5) &&
         rayClearsMove(c, curve_, q, 1, 0.5, 1)))
      return {};
  }
  // Step 6: the rim contact located by Newton's method over (t, phi) from the knots'
  // start (rim_contact.h), and its height proven lowest at once by step 4b's ray
  // clearance: on corner contacts (every bull and ball on CAM paths) no stationary
  // search at all. Where Newton stops or the proof fails (flat faces, flanks, a line
  // leaving the cutter), the face or the certified search (certified_search.h) decides.
  if (!c.general() && c.cornerRadius > 0) {
    RimContact rim = locateRimContact(c, curve_, x, y, start);
    // A knots' start too far for Newton (coarse knots, a contact that jumps between
    // them): once more from the middle.
    if (!rim.found && start.hasDirection) rim = locateRimContact(c, curve_, x, y);
    if (rim.found && rayClearsMove(c, curve_, {x, y, rim.z - kProofGap}, rim.pose, 0, 1)) {
      if (!(rim.z < cutoff)) return {};
      out.hit = true, out.z = rim.z, out.normal = rim.normal, out.t = rim.t;
      return out;
    }
  }
  if (faceContact && !faceTried && face(out)) return out;
  return certifiedLowestPoint(c, curve_, {reach_, zTop_, tipSpeed_}, x, y, cutoff);
}

}  // namespace scallop
