// TipBall: the fast path of a general cutter whose profile starts with a ball tip (tapered
// ball, taper barrel, oval: a first arc of radius r centred on the axis at s = r).
//
// The cutter K splits at the tip arc's end s_t into the cap K n {s <= s_t}, a part of
// the ball B of radius r about the axis point s = r, and the rest K n {s >= s_t}.
// Wherever the next segment is a line tangent to the ball or an arc of radius >= r
// tangent to it from outside and reaching s = r, the hemisphere H = B n {s <= r} lies in
// K (that segment stays outside the ball's circle up to s = r), so
//     K n {s <= s_t}  c  H  c  K,   K  c  H u Rest.
// Swept over a move, the hemisphere's lowest point on a vertical line (the ball kernel's,
// exact, with its own proof) is a height of the solid, an upper bound U; the solid's
// height is min(U, lowest point of the swept Rest). A plane n . p = H(n) that holds the
// swept Rest below it (restLowerBound) bounds that second term from below, so where it
// lies above U the height is U, proven as the ball kernel proves it.
//
// Rest's support: a point of K maximising n . p lies in Rest (then h_Rest = h_K), or the
// maximum over Rest lies on its boundary plane s = s_t (a linear function on a convex set
// cut by a half-space), the disc of radius w(s_t): s_t n_a + w(s_t) |n_perp|. Over a
// move whose axis turns at most omega per unit t about the tip, h_Rest(R(t)^T n) moves
// by at most reach omega |t - 1/2| from its value at t = 1/2 (support functions are
// |p|-Lipschitz), and n . tip(t) is linear for a linear tip: the plane's offset is
//     H(n) = h_Rest(at t = 1/2) + reach omega / 2 + max(n . tip(0), n . tip(1)).
#pragma once

#include "base/vec3.h"
#include "sweep/cutter.h"
#include "sweep/pose_curve.h"

namespace scallop {

struct TipBall {
  bool valid = false;     // the profile has a ball tip as the header says
  double radius = 0;      // r, mm
  double splitS = 0;      // s_t: where the tip arc ends, mm above the tip
  double splitWidth = 0;  // w(s_t), mm
};

// The ball tip of a general cutter's profile, or !valid.
TipBall tipBallOf(const Cutter& cutter);

// The ball cutter (radius r, flute length r: the hemisphere H) of a valid tip ball.
Cutter tipBallCutter(const TipBall& ball);

// The swept Rest of one move (a linear tip only: curve.linearTip()), what its bound needs
// computed once.
class SweptRest {
 public:
  SweptRest(const Cutter& cutter, const TipBall& ball, const PoseCurve& curve);
  // A proven lower bound of the lowest point of the swept Rest on the vertical line
  // through (x, y), from the plane of normal `n` (n.z < 0, any length).
  double lowerBound(const Vec3& n, double x, double y) const;
  // <= every z the swept Rest reaches (the bound with n = -z), mm.
  double floor() const { return floor_; }

 private:
  const CutterProfile* profile_;
  TipBall ball_;
  Vec3 axis_, tip0_, tip1_;  // the axis at t = 1/2, the tip at t = 0 and 1
  double turn_ = 0;          // reach omega / 2: how far the rotation moves a support, mm
  double scale_ = 0;         // mm: the coordinates' size, for round-off
  double floor_ = 0;
};

}  // namespace scallop
