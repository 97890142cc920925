// IntervalBounds: step 2 of the certified search (certified_search.cpp), the proven
// lower bounds of f(t), a turning move's lowest point on a vertical line, over an
// interval of t between two samples; and the chord bound of the move's support
// function that SweptMove::support shares. Internal to sweep/: CertifiedSearch is its
// one user. The derivation is in interval_bounds.cpp.
#pragma once

#include <cmath>

#include "sweep/certified_search.h"
#include "sweep/cutter.h"
#include "sweep/pose_curve.h"

namespace scallop {

// f at one t: the lowest point of K(t) on the line, and the plane to bound neighbours
// with. The search keeps its samples in raw storage and constructs each one as it is
// taken: Vec3's member initialisers would otherwise zero all of them (200 KB) on every
// search, which was 15 % of B3's time.
struct SearchSample {
  double t;
  Vec3 tip, axis;
  double z;       // f(t), mm; +inf when the line misses K(t)
  Vec3 normal;    // unit, normal.z < 0; zero when no plane is known
  double hOwn;    // support of K(t) - tip(t) in `normal` (every bound needs it)
  double slope;   // df/dt where known, else NaN
  Vec3 vel, acc;  // d tip / dt and d^2 tip / dt^2 at t
  Vec3 dn, ddn;   // d/dt and d2/dt2 of `normal` carried with the cutter (steps 2b, 2d)
};

// What the bounds need of the tip's motion: where it is linear (CL data, TCP on), its
// chord p1 - p0, which is its velocity; on a curve (TCP off, pose_curve.h) bounds of its
// speed and acceleration over [0, 1], mm per unit t and t^2.
struct TipMotionBounds {
  Vec3 delta;
  bool linear;
  double speed;  // >= |tip'(t)|: |delta| when linear
  double accel;  // >= |tip''(t)|: 0 when linear
  double jerk;   // >= |tip'''(t)|: 0 when linear
  // An arc's curve (its bounds along a direction are smaller: PoseCurve::tipAccelAlong);
  // null for the other kinds.
  const PoseCurve* arc = nullptr;
  // Bounds of |N . tip'(t)|, |N . tip''(t)| and |N . tip'''(t)| over the move, N unit.
  double rateAlong(const Vec3& N) const {
    if (arc) return arc->tipRateAlong(N);
    return linear ? std::fabs(dot(N, delta)) : speed;
  }
  double accelAlong(const Vec3& N) const { return arc ? arc->tipAccelAlong(N) : accel; }
  double jerkAlong(const Vec3& N) const { return arc ? arc->tipJerkAlong(N) : jerk; }
};

// The lower bounds of f on the vertical line through (x, y) over [a.t, b.t], a.t < b.t,
// each from the samples at the ends (hOwn known) and less its round-off.
class IntervalBounds {
 public:
  IntervalBounds(const Cutter& cutter, const PoseCurve& curve, const TurningBounds& bounds,
                 double x, double y);

  // Step 2a: the world-fixed plane of `from` (a or b), -inf where it has none.
  double worldPlane(const SearchSample& from, const SearchSample& a, const SearchSample& b) const;
  // Step 2b: the plane fixed to the cutter at `from`, carried to `to` (the other end),
  // claimed for heights up to U; -inf where it may turn horizontal.
  double cutterPlane(const SearchSample& from, const SearchSample& to, const SearchSample& a,
                     const SearchSample& b, double U) const;
  // Step 2c: the grown cutter at the middle pose; +inf where the line misses it.
  double grownCutter(const SearchSample& a, const SearchSample& b) const;
  // Step 2d: whether height z is proven below every K(t), t in [a.t, b.t], by the
  // Taylor form at `from` (a, b or any sample inside).
  bool taylorProves(const SearchSample& from, const SearchSample& a, const SearchSample& b,
                    double z) const;
  // Step 2e: whether the line provably misses every K(t), t in [a.t, b.t], passing beside
  // the flank below the flute top's plane and above that plane inside the flank's
  // extension (ball, flat and bull cutters; false proves nothing).
  bool missesBesideFluteTop(const SearchSample& a, const SearchSample& b) const;

 private:
  double thirdDerivative(double D, const Vec3& N) const;
  bool carriedPlanePositive(const SearchSample& from, const SearchSample& a, const SearchSample& b,
                            double z) const;
  double distanceBound(const SearchSample& a, const SearchSample& b, double zLow,
                       double zHigh) const;

  const Cutter& c_;
  const PoseCurve& curve_;
  const TurningBounds& bounds_;
  const double x_, y_;
  const double omega_;  // the curve's turn rate, rad per unit t
  const TipMotionBounds tip_;
};

// The horizontal unit direction from the footprint of the axis segment [tip, tip + L a]
// to (x, y), leaned 1e-3 downwards: a steep plane that rises 1 mm per um outside the
// cutter's shadow, for a sample whose lowest point gives none. Zero when (x, y) lies on
// the shadow of the axis itself.
Vec3 steepNormal(const Cutter& c, const Vec3& tip, const Vec3& a, double x, double y);

}  // namespace scallop
