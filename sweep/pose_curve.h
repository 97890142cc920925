// PoseCurve: where the cutter is at each instant t in [0, 1] of one move
// (CONVENTIONS.md "Tool pose", "Machines").
//
// Every curve has a tip moving linearly, tip(t) = p0 + t (p1 - p0), and a tool axis that
// turns as a rigid rotation R(t) of the cutter about its tip: axis(t) = R(t) axis_body.
// What the swept-solid kernel (swept_move.cpp) needs of a curve, besides pose(t), is one
// number: the turn rate omega (rad per unit t), a bound such that every point k of the
// cutter (tip at the origin) satisfies
//     |d/dt R(t) k| <= omega |k|     and     |d^2/dt^2 R(t) k| <= omega^2 |k|.
// The kinds:
//   * Slerp (CL data): the great circle from a0 to a1 at constant angular speed phi
//     (the angle between them), a rotation about the fixed axis w = a0 x a1 / |.|:
//     R'k = phi w x Rk, R''k = -phi^2 (the part of Rk across w): omega = phi.
//   * Rotary (5-axis machines with TCP on): two rotary angles, each linear in t, the
//     axis a product of two rotations R = A(theta1(t)) B(theta2(t)) at constant rates
//     w1, w2: R' = A'B + AB', R'' = A''B + 2A'B' + AB'', so omega = |w1| + |w2|.
//     Kinematics xyzbc-trt (axis = (-cos C sin B, sin C sin B, cos B)) and xyzac-trt
//     (axis = (sin C sin A, cos C sin A, cos A)), as LinuxCNC's trtfuncs define them.
//   * Joint-linear (5-axis table-table machines with TCP off): the joints X Y Z and
//     the rotary angles move linearly in t and the tip in the part frame is the
//     machine's forward kinematics (trtfuncs' xyzbcKinematicsForward and
//     xyzacKinematicsForward), with q(t) = joints(t) - offset' - pivot linear:
//         tip(t) = Rz(-C) (Rt(-T) q(t) + e) + pivot + (0, 0, offset.z),
//     Rt = Ry (xyzbc-trt, e = (offset.x, 0, 0), offset' = (offset.x, 0, offset.z)) or
//     Rx (xyzac-trt, e = (0, offset.y, 0), offset' = (0, offset.y, offset.z)). The
//     axis and its rotation are the rotary kind's, so omega is too; the tip is NOT
//     linear in t. With M = Rz(-C) Rt(-T), |M^(n) v| <= omega^n |v| (the product rule
//     as above), q'' = 0 and |q(t)| <= max(|q(0)|, |q(1)|) = Q (|q| is convex in t):
//         |tip''|  <= omega^2 Q + 2 omega |q'| + |wC|^2 |e|,
//         |tip'''| <= omega^3 Q + 3 omega^2 |q'| + |wC|^3 |e|   (tipAccelBound/JerkBound).
//   * Arc (G-code G2/G3, pose.h ArcMotion): the axis constant (omega = 0), the tip on
//     a circle or helix, tip = centre + rho e_r + rise t n with e_r = cos theta u +
//     sin theta v, e_theta = n x e_r = -sin theta u + cos theta v, theta' = s (the
//     sweep), rho' = d (radius1 - radius0), so e_r' = s e_theta, e_theta' = -s e_r and
//         tip'   = d e_r + rho s e_theta + rise n,
//         tip''  = 2 d s e_theta - rho s^2 e_r,
//         tip''' = -3 d s^2 e_r - rho s^3 e_theta,
//     the parts orthogonal: |tip''| = sqrt(4 d^2 s^2 + rho^2 s^4) and |tip'''| =
//     sqrt(9 d^2 s^4 + rho^2 s^6), at most their values at rho = max(radius0, radius1)
//     (rho is linear in t); on a circle (d = 0) exactly r s^2 and r |s|^3, and the
//     speed sqrt(d^2 + rho^2 s^2 + rise^2) likewise. The bounds keep 1e-12 relative
//     for their round-off.
// A new machine curve is a new kind with its own axis(t), omega and, for a curved tip,
// tipVelocity, tipAcceleration and the bounds: the kernel (swept_move.cpp,
// ray_clearance.cpp) takes the tip's speed, acceleration and jerk into its bounds.
#pragma once

#include <memory>

#include "base/vec3.h"
#include "sweep/pose.h"

namespace scallop {

// The tool axis of a table-table machine at tilt (B or A) and spin (C), radians, in the
// part frame (CONVENTIONS.md "Machines").
Vec3 machineAxis(RotaryKinematics kinematics, double tilt, double spin);
// The forward kinematics of `machine`: the tool tip in the part frame for the joints
// X Y Z (mm) at tilt and spin (radians), LinuxCNC's trtfuncs formulas.
Vec3 machineTip(const TableMachine& machine, const Vec3& joints, double tilt, double spin);

// Everything the kernel asks of a curve at one t, computed together (one sine and cosine
// for slerp): see PoseCurve's accessors of the same names and PoseCurve::frame.
struct PoseFrame {
  double t = 0;
  Vec3 tip, velocity, acceleration;  // tip(t), tipVelocity(t), tipAcceleration(t)
  Vec3 axis, e1, e2;                 // axis(t) and the turning frame across it
  Vec3 spin, spinRate;               // spin(t), spinRate(t)
};

class PoseCurve {
 public:
  // CL data: tip linear, axis = slerp(a0, a1, t). Axes are normalised here. Throws
  // InputError (where = `where`) for a turn of 180 degrees, whose great circle is
  // undefined.
  static PoseCurve linear(const Pose& from, const Pose& to, const char* where = "path move");
  // Whether slerp from a0 to a1 turns (by more than the 1e-12 rad treated as none).
  static bool turns(const Vec3& a0, const Vec3& a1);
  // A table-table machine with TCP on: tip linear, rotary angles (radians) linear in t.
  static PoseCurve rotary(RotaryKinematics kinematics, const Vec3& tip0, const Vec3& tip1,
                          double tilt0, double tilt1, double spin0, double spin1);

  // A table-table machine with TCP off: joints and angles (radians) linear in t, the
  // tip the forward kinematics of `machine` (above).
  static PoseCurve jointLinear(const TableMachine& machine, const RotaryMotion& motion);
  // A G-code arc: the tip on `arc` (pose.h), the axis `axis` (normalised here) for the
  // whole move.
  static PoseCurve arc(const ArcMotion& arc, const Vec3& axis);
  // The curve of `move` of `path`: its machine motion when it has one (Move::rotary),
  // its arc (Move::arc), otherwise linear(move.from, move.to, where).
  static PoseCurve ofMove(const ToolPath& path, const Move& move, const char* where = "path move");
  // The same motion reflected through the plane z = 0 (every pose's z negated), for the
  // slerp and arc kinds: the highest point of this curve's swept solid on a vertical line
  // is minus the lowest point of the mirror's. False for the machines' kinds, whose poses
  // are machine angles.
  bool mirroredZ(PoseCurve* out) const;

  Vec3 tip(double t) const {
    if (t >= 1) return tip1_;
    if (!linearTip()) return t <= 0 ? tip0_ : kind_ == Kind::Arc ? arc_->motion.at(t) : forward(t);
    return tip0_ + (tip1_ - tip0_) * t;
  }
  // d tip / dt (mm per unit t).
  Vec3 tipVelocity(double t) const { return linearTip() ? tip1_ - tip0_ : curvedTipVelocity(t); }
  // d^2 tip / dt^2 (mm per unit t^2): zero for the kinds whose tip is linear.
  Vec3 tipAcceleration(double t) const { return linearTip() ? Vec3{} : curvedTipAcceleration(t); }
  // Proven bounds over [0, 1] of |d^2 tip / dt^2| and |d^3 tip / dt^3| (mm per unit
  // t^2, t^3): 0 for the kinds whose tip is linear.
  double tipAccelBound() const { return tipAccel_; }
  double tipJerkBound() const { return tipJerk_; }
  // For a unit direction N, bounds over [0, 1] of |N . tip'|, |N . tip''| and
  // |N . tip'''|: those of the tip's speed, acceleration and jerk, except on an arc,
  // whose tip'' and tip''' lie in its plane and whose tip' leaves it by the rise alone:
  // there |N . tip^(k)| <= |N across the normal| times the in-plane bound (k = 2, 3),
  // and |N . tip'| <= |N . n| |rise| + |N across n| sqrt(d^2 + rho_max^2 s^2). (On a
  // horizontal circle a plane of normal z sees no acceleration at all.)
  double tipRateAlong(const Vec3& N) const;
  double tipAccelAlong(const Vec3& N) const;
  double tipJerkAlong(const Vec3& N) const;
  // A proven bound over [0, 1] of |d tip / dt| (mm per unit t): |p1 - p0| for the kinds
  // whose tip is linear; on a curve |tip'(t)| <= |tip'(end)| + A |t - end| for the
  // nearer end, at most the larger end speed plus A / 2.
  double tipSpeedBound() const;
  bool linearTip() const { return kind_ < Kind::JointBC; }
  // The tip follows a G-code arc (PoseCurve::arc).
  bool arcTip() const { return kind_ == Kind::Arc; }
  // The length of the tip's path, mm: the chord for a linear tip, the arc's length
  // for an arc (closed form on a circle or helix; Simpson's rule on 64 intervals for a
  // spiral, whose speed varies by at most 0.002 mm / radius relative); the end-to-end
  // chord for the joint-linear kind (the teeth model refuses it).
  double pathLength() const;
  Vec3 axis(double t) const;
  Pose pose(double t) const { return {tip(t), axis(t)}; }
  // The cutter's angular velocity Omega(t) (rad per unit t; a direction n fixed to the
  // cutter has n' = Omega x n) and its derivative Omega'(t).
  Vec3 spin(double t) const {
    if (omega_ == 0) return {};
    return kind_ == Kind::Slerp ? w_ * phi_ : rotarySpin(t);  // slerp: a fixed axis, constant rate
  }
  Vec3 spinRate(double t) const;
  // The pose at t with two unit directions e1, e2 across the axis, fixed to the cutter
  // (carried by R(t)), so that (e1, e2, axis) is a right-handed orthonormal frame turning
  // with the cutter: a cutter point k = alpha e1 + beta e2 + s axis has dk/dt = spin x k.
  // For slerp e1 is the fixed turning axis itself (no trigonometry beyond axis(t)).
  PoseFrame frame(double t) const {
    PoseFrame f;
    frame(t, f);
    return f;
  }
  // The same, written into `f` (no copy of its ten vectors).
  void frame(double t, PoseFrame& f) const;
  // A direction fixed to the cutter, carried from its pose at ta to its pose at tb:
  // R(tb) R(ta)^-1 v. (Planes fixed to the cutter move with it: interval_bounds.cpp.)
  Vec3 carry(const Vec3& v, double ta, double tb) const;

  const Vec3& tipStart() const { return tip0_; }
  const Vec3& tipEnd() const { return tip1_; }
  double turnRate() const { return omega_; }  // omega above, rad per unit t
  // The axis never turns: the constant-axis kernel is exact for it. True when the turn
  // is below 1e-12 rad, where no cutter point strays by more than reach * 1e-12 mm.
  bool constantAxis() const { return omega_ == 0; }

 private:
  // The kinds whose tip is linear come first (linearTip).
  enum class Kind : unsigned char { Slerp, TableBC, TableAC, JointBC, JointAC, Arc };
  bool tableBC() const { return kind_ == Kind::TableBC || kind_ == Kind::JointBC; }
  // Joint-linear: the forward kinematics at t of the linear joints, and its derivatives.
  Vec3 forward(double t) const;
  Vec3 curvedTipVelocity(double t) const;
  Vec3 curvedTipAcceleration(double t) const;
  Vec3 rotarySpin(double t) const;
  Kind kind_ = Kind::Slerp;
  Vec3 tip0_, tip1_;
  // Slerp: axis(t) = u_ cos(phi t) + v_ sin(phi t), with u_ = a0, v_ the unit vector
  // across it towards a1, and the exact end axis a1_ returned at t = 1.
  Vec3 u_, v_, a1_;
  Vec3 w_;  // u_ x v_, the unit axis the cutter turns about

  Vec3 axisMiddle_;  // axis(0.5), computed once
  double phi_ = 0;
  double omega_ = 0;
  double tipAccel_ = 0, tipJerk_ = 0;
  // What only the machines' and the arcs' curves need, shared (most moves are slerps, and
  // a scene holds one curve a move: 392 bytes with these inline, 264 without).
  struct MachineTerms {
    // Rotary: tilt (B or A) and spin (C) angles at t = 0 and their changes, radians.
    double tilt0 = 0, dTilt = 0, spin0 = 0, dSpin = 0;
    // Joint-linear: q(t) = q0 + t dq, the offset e and the constant c above, mm.
    Vec3 q0, dq, e, c;
  };
  struct ArcTerms {
    ArcMotion motion;       // the tip's circle or helix
    double speed = 0;       // >= |tip'| over the move, mm per unit t
    double planeSpeed = 0;  // >= |tip' - rise n|, mm per unit t
    Vec3 normal;            // n = u x v
  };
  std::shared_ptr<const MachineTerms> machine_;
  std::shared_ptr<const ArcTerms> arc_;
  double arcAcross(const Vec3& N) const;
};

}  // namespace scallop
