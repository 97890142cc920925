#include "sweep/pose_curve.h"

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

namespace {

// Turns smaller than this (rad) are treated as none: no cutter point then strays by
// more than reach * 1e-12 mm from the constant-axis solid.
constexpr double kNoTurn = 1e-12;

// Rotations of v about the coordinate axes by `angle` (right-handed).
Vec3 rotX(const Vec3& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}
Vec3 rotY(const Vec3& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}
Vec3 rotZ(const Vec3& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// sin and cos of a slerp's angle. The turns of CAM moves are small (B3: ~0.01 rad), where
// the Taylor series to a^11 and a^12 is within 1e-18 of both for |a| <= 1/4, below
// their rounding (as good as the library's, which costs ~5 times as much); larger
// angles go to the library.
void sinCos(double a, double& s, double& c) {
  if (!(std::fabs(a) <= 0.25)) {
    s = std::sin(a), c = std::cos(a);
    return;
  }
  const double a2 = a * a;
  s = a +
      a * a2 *
          (-1.0 / 6 + a2 * (1.0 / 120 + a2 * (-1.0 / 5040 + a2 * (1.0 / 362880 - a2 / 39916800))));
  c = 1 + a2 * (-0.5 + a2 * (1.0 / 24 +
                             a2 * (-1.0 / 720 +
                                   a2 * (1.0 / 40320 + a2 * (-1.0 / 3628800 + a2 / 479001600)))));
}

double clampUnit(double t) {
  return std::clamp(t, 0.0, 1.0);
}

// The constant parts of the forward kinematics (pose_curve.h): q = joints - d - pivot,
// tip = Rz(-C) (Rt(-T) q + e) + c.
struct Kinematics {
  Vec3 d, e, c;
};
Kinematics kinematicsOf(const TableMachine& m) {
  const Vec3 o = m.offset;
  const Vec3 c = m.pivot + Vec3{0, 0, o.z};
  if (m.kinematics == RotaryKinematics::TableBC) return {{o.x, 0, o.z}, {o.x, 0, 0}, c};
  return {{0, o.y, o.z}, {0, o.y, 0}, c};
}

Vec3 tiltRotation(bool bc, const Vec3& v, double angle) {
  return bc ? rotY(v, angle) : rotX(v, angle);
}

}  // namespace

Vec3 machineAxis(RotaryKinematics kin, double tilt, double spin) {
  const double st = std::sin(tilt), ct = std::cos(tilt);
  if (kin == RotaryKinematics::TableBC) return {-std::cos(spin) * st, std::sin(spin) * st, ct};
  return {std::sin(spin) * st, std::cos(spin) * st, ct};
}

Vec3 machineTip(const TableMachine& machine, const Vec3& joints, double tilt, double spin) {
  const Kinematics k = kinematicsOf(machine);
  const bool bc = machine.kinematics == RotaryKinematics::TableBC;
  return rotZ(tiltRotation(bc, joints - k.d - machine.pivot, -tilt) + k.e, -spin) + k.c;
}

namespace {

// The angle between unit axes from atan2 of the cross and dot products: accurate for
// small and near-straight turns alike (acos loses half the digits near 0 and pi).
double turnAngle(const Vec3& a0, const Vec3& a1) {
  return std::atan2(length(cross(a0, a1)), dot(a0, a1));
}

}  // namespace

bool PoseCurve::turns(const Vec3& a0, const Vec3& a1) {
  return turnAngle(normalize(a0), normalize(a1)) > kNoTurn;
}

PoseCurve PoseCurve::linear(const Pose& from, const Pose& to, const char* where) {
  PoseCurve c;
  c.kind_ = Kind::Slerp;
  c.tip0_ = from.tip;
  c.tip1_ = to.tip;
  const Vec3 a0 = normalize(from.axis), a1 = normalize(to.axis);
  c.u_ = a0;
  c.a1_ = a1;
  const double phi = turnAngle(a0, a1);
  if (phi > kPi - 1e-9)
    throw InputError(where, "the axis turns by 180 degrees; the rotation is undefined");
  if (phi <= kNoTurn) {
    c.a1_ = a0;  // one axis for the whole move
    return c;
  }
  c.phi_ = phi;
  c.v_ = normalize(a1 - a0 * dot(a0, a1));
  c.w_ = cross(c.u_, c.v_);
  c.omega_ = phi;
  double sh, ch;
  sinCos(phi * 0.5, sh, ch);
  c.axisMiddle_ = c.u_ * ch + c.v_ * sh;  // axis(0.5)
  return c;
}

PoseCurve PoseCurve::rotary(RotaryKinematics kin, const Vec3& tip0, const Vec3& tip1, double tilt0,
                            double tilt1, double spin0, double spin1) {
  PoseCurve c;
  c.kind_ = kin == RotaryKinematics::TableBC ? Kind::TableBC : Kind::TableAC;
  c.tip0_ = tip0;
  c.tip1_ = tip1;
  MachineTerms m;
  m.tilt0 = tilt0, m.dTilt = tilt1 - tilt0;
  m.spin0 = spin0, m.dSpin = spin1 - spin0;
  c.u_ = machineAxis(kin, tilt0, spin0);
  c.a1_ = machineAxis(kin, tilt1, spin1);
  c.omega_ = std::fabs(m.dTilt) + std::fabs(m.dSpin);
  c.machine_ = std::make_shared<const MachineTerms>(m);
  if (c.omega_ <= kNoTurn) c.omega_ = 0, c.a1_ = c.u_;
  return c;
}

namespace {
// A direction not parallel to the unit vector a.
Vec3 acrossHelper(const Vec3& a) {
  return std::fabs(a.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
}
}  // namespace

PoseCurve PoseCurve::jointLinear(const TableMachine& machine, const RotaryMotion& m) {
  const bool bc = machine.kinematics == RotaryKinematics::TableBC;
  PoseCurve c =
      rotary(machine.kinematics, machineTip(machine, m.joints0, m.tilt0, m.spin0),
             machineTip(machine, m.joints1, m.tilt1, m.spin1), m.tilt0, m.tilt1, m.spin0, m.spin1);
  if (c.omega_ == 0) return c;  // constant angles: the rotation is fixed, the tip linear
  c.kind_ = bc ? Kind::JointBC : Kind::JointAC;
  const Kinematics k = kinematicsOf(machine);
  MachineTerms terms = *c.machine_;
  terms.q0 = m.joints0 - k.d - machine.pivot;
  terms.dq = m.joints1 - m.joints0;
  terms.e = k.e;
  terms.c = k.c;
  c.machine_ = std::make_shared<const MachineTerms>(terms);
  // The bounds of pose_curve.h, from the rates before any rounding to zero.
  const double w = std::fabs(terms.dTilt) + std::fabs(terms.dSpin), wc = std::fabs(terms.dSpin);
  const double Q = std::fmax(length(terms.q0), length(terms.q0 + terms.dq)), dq = length(terms.dq);
  const double e = length(terms.e);
  c.tipAccel_ = w * w * Q + 2 * w * dq + wc * wc * e;
  c.tipJerk_ = w * w * w * Q + 3 * w * w * dq + wc * wc * wc * e;
  return c;
}

PoseCurve PoseCurve::arc(const ArcMotion& arc, const Vec3& axis) {
  PoseCurve c;
  c.kind_ = Kind::Arc;

  c.tip0_ = arc.at(0);
  c.tip1_ = arc.at(1);
  c.u_ = c.a1_ = c.axisMiddle_ = normalize(axis);
  // The bounds of pose_curve.h at the larger radius, 1e-12 relative for round-off.
  const double s = std::fabs(arc.sweep), d = std::fabs(arc.radius1 - arc.radius0);
  const double rho = std::fmax(arc.radius0, arc.radius1), keep = 1 + 1e-12;
  ArcTerms terms;
  terms.motion = arc;
  terms.speed = std::sqrt(d * d + rho * rho * s * s + arc.rise * arc.rise) * keep;
  terms.planeSpeed = std::sqrt(d * d + rho * rho * s * s) * keep;
  terms.normal = cross(arc.u, arc.v);
  c.arc_ = std::make_shared<const ArcTerms>(terms);
  c.tipAccel_ = std::sqrt(4 * d * d * s * s + rho * rho * s * s * s * s) * keep;
  c.tipJerk_ = std::sqrt(9 * d * d * s * s * s * s + rho * rho * s * s * s * s * s * s) * keep;
  return c;
}

bool PoseCurve::mirroredZ(PoseCurve* out) const {
  auto flip = [](const Vec3& p) { return Vec3{p.x, p.y, -p.z}; };
  if (kind_ == Kind::Slerp) {
    *out = linear({flip(tip0_), flip(u_)}, {flip(tip1_), flip(a1_)});
    return true;
  }
  if (kind_ != Kind::Arc) return false;
  // The circle's u and v reflect; n = u x v then turns the other way (a reflection is
  // improper), so the rise along it changes sign.
  ArcMotion arc = arc_->motion;
  arc.centre = flip(arc.centre), arc.u = flip(arc.u), arc.v = flip(arc.v), arc.rise = -arc.rise;
  *out = PoseCurve::arc(arc, flip(u_));
  return true;
}

PoseCurve PoseCurve::ofMove(const ToolPath& path, const Move& move, const char* where) {
  if (move.arc > 0) return arc(path.arcs.at(move.arc - 1), move.from.axis);
  if (move.rotary == 0) return linear(move.from, move.to, where);
  const RotaryMotion& m = path.rotary.at(move.rotary - 1);
  if (!m.tcp) return jointLinear(path.machine, m);
  return rotary(path.machine.kinematics, move.from.tip, move.to.tip, m.tilt0, m.tilt1, m.spin0,
                m.spin1);
}

Vec3 PoseCurve::forward(double t) const {
  const bool bc = kind_ == Kind::JointBC;
  const double tilt = machine_->tilt0 + machine_->dTilt * t,
               spin = machine_->spin0 + machine_->dSpin * t;
  return rotZ(tiltRotation(bc, machine_->q0 + machine_->dq * t, -tilt) + machine_->e, -spin) +
         machine_->c;
}

Vec3 PoseCurve::curvedTipVelocity(double t) const {
  if (kind_ == Kind::Arc) {
    const ArcMotion& a = arc_->motion;
    const double theta = a.angle0 + a.sweep * t, rho = a.radius0 + (a.radius1 - a.radius0) * t;
    const double c = std::cos(theta), s = std::sin(theta);
    const Vec3 er = a.u * c + a.v * s, et = a.v * c - a.u * s;
    return er * (a.radius1 - a.radius0) + et * (rho * a.sweep) + cross(a.u, a.v) * a.rise;
  }
  // tip = Z(phi) (T(psi) q + e) + c with phi = -C(t), psi = -T(t); a rotation about the
  // unit axis n by angle a has d/da R v = n x R v.
  const bool bc = kind_ == Kind::JointBC;
  const double tilt = machine_->tilt0 + machine_->dTilt * t,
               spin = machine_->spin0 + machine_->dSpin * t;
  const Vec3 tq = tiltRotation(bc, machine_->q0 + machine_->dq * t, -tilt);
  const Vec3 n = bc ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 inner = cross(n, tq) * -machine_->dTilt + tiltRotation(bc, machine_->dq, -tilt);
  return cross(Vec3{0, 0, 1}, rotZ(tq + machine_->e, -spin)) * -machine_->dSpin +
         rotZ(inner, -spin);
}

double PoseCurve::tipSpeedBound() const {
  if (linearTip()) return length(tip1_ - tip0_);
  if (kind_ == Kind::Arc) return arc_->speed;
  return std::max(length(tipVelocity(0)), length(tipVelocity(1))) + 0.5 * tipAccel_;
}

double PoseCurve::arcAcross(const Vec3& N) const {
  const double along = dot(N, arc_->normal);
  return std::sqrt(std::max(0.0, dot(N, N) - along * along)) * (1 + 1e-12);
}

double PoseCurve::tipRateAlong(const Vec3& N) const {
  if (kind_ != Kind::Arc) return linearTip() ? std::fabs(dot(N, tip1_ - tip0_)) : tipSpeedBound();
  return (std::fabs(dot(N, arc_->normal) * arc_->motion.rise) + arcAcross(N) * arc_->planeSpeed) *
         (1 + 1e-12);
}

double PoseCurve::tipAccelAlong(const Vec3& N) const {
  return kind_ == Kind::Arc ? arcAcross(N) * tipAccel_ : tipAccel_;
}

double PoseCurve::tipJerkAlong(const Vec3& N) const {
  return kind_ == Kind::Arc ? arcAcross(N) * tipJerk_ : tipJerk_;
}

double PoseCurve::pathLength() const {
  if (kind_ != Kind::Arc) return length(tip1_ - tip0_);
  const ArcMotion& a = arc_->motion;
  const double d = a.radius1 - a.radius0;
  auto speed = [&](double t) {
    const double rho = a.radius0 + d * t;
    return std::sqrt(d * d + rho * rho * a.sweep * a.sweep + a.rise * a.rise);
  };
  if (d == 0) return speed(0);
  constexpr int kIntervals = 64;
  double sum = speed(0) + speed(1);
  for (int i = 1; i < kIntervals; ++i) sum += (i % 2 ? 4 : 2) * speed(double(i) / kIntervals);
  return sum / (3 * kIntervals);
}

Vec3 PoseCurve::curvedTipAcceleration(double t) const {
  if (kind_ == Kind::Arc) {
    const ArcMotion& a = arc_->motion;
    const double theta = a.angle0 + a.sweep * t, rho = a.radius0 + (a.radius1 - a.radius0) * t;
    const double c = std::cos(theta), s = std::sin(theta);
    const Vec3 er = a.u * c + a.v * s, et = a.v * c - a.u * s;
    return et * (2 * (a.radius1 - a.radius0) * a.sweep) - er * (rho * a.sweep * a.sweep);
  }
  // With P = T(psi) q and W = P + e: P' = -dT n x P + T dq, P'' = -dT n x (P' + T dq);
  // tip' = -dC z x (Z W) + Z P', so tip'' = -dC z x (tip' + Z P') + Z P''.
  const bool bc = kind_ == Kind::JointBC;
  const double tilt = machine_->tilt0 + machine_->dTilt * t,
               spin = machine_->spin0 + machine_->dSpin * t;
  const Vec3 n = bc ? Vec3{0, 1, 0} : Vec3{1, 0, 0}, z{0, 0, 1};
  const Vec3 tq = tiltRotation(bc, machine_->q0 + machine_->dq * t, -tilt),
             tdq = tiltRotation(bc, machine_->dq, -tilt);
  const Vec3 p1 = cross(n, tq) * -machine_->dTilt + tdq;
  const Vec3 p2 = cross(n, p1 + tdq) * -machine_->dTilt;
  const Vec3 zp1 = rotZ(p1, -spin);
  const Vec3 v = cross(z, rotZ(tq + machine_->e, -spin)) * -machine_->dSpin + zp1;
  return cross(z, v + zp1) * -machine_->dSpin + rotZ(p2, -spin);
}

Vec3 PoseCurve::axis(double t) const {
  if (omega_ == 0 || t <= 0) return u_;
  if (t >= 1) return a1_;
  if (kind_ == Kind::Slerp) {
    // The middle, where every search starts, is kept: the same bits without the sine.
    if (t == 0.5) return axisMiddle_;
    double sa, ca;
    sinCos(phi_ * t, sa, ca);
    return u_ * ca + v_ * sa;
  }
  const RotaryKinematics kin = tableBC() ? RotaryKinematics::TableBC : RotaryKinematics::TableAC;
  return machineAxis(kin, machine_->tilt0 + machine_->dTilt * t,
                     machine_->spin0 + machine_->dSpin * t);
}

Vec3 PoseCurve::carry(const Vec3& v, double ta, double tb) const {
  if (omega_ == 0 || ta == tb) return v;
  if (kind_ == Kind::Slerp) {
    // Rodrigues' formula about w = u x v (unit: u_ and v_ are orthonormal).
    const Vec3& w = w_;
    double s, c;
    sinCos(phi_ * (tb - ta), s, c);
    return v * c + cross(w, v) * s + w * (dot(w, v) * (1 - c));
  }
  // The cutter's rotation is R(t) = Rz(-C) Ry(-B) (xyzbc-trt) or Rz(-C) Rx(-A)
  // (xyzac-trt), mapping +Z to axis(t): undo it at ta, apply it at tb.
  const double tiltA = machine_->tilt0 + machine_->dTilt * ta,
               spinA = machine_->spin0 + machine_->dSpin * ta;
  const double tiltB = machine_->tilt0 + machine_->dTilt * tb,
               spinB = machine_->spin0 + machine_->dSpin * tb;
  if (tableBC()) return rotZ(rotY(rotY(rotZ(v, spinA), tiltA), -tiltB), -spinB);
  return rotZ(rotX(rotX(rotZ(v, spinA), tiltA), -tiltB), -spinB);
}

void PoseCurve::frame(double t, PoseFrame& f) const {
  f.t = t;
  f.tip = tip(t);
  f.velocity = tipVelocity(t);
  f.acceleration = tipAcceleration(t);
  f.axis = axis(t);
  if (kind_ == Kind::Slerp || kind_ == Kind::Arc) {
    // The rotation is about w = u x v, which lies across every axis of the move (an
    // arc's axis does not turn).
    f.e1 = omega_ > 0 ? w_ : normalize(cross(u_, acrossHelper(u_)));
    f.spin = omega_ > 0 ? w_ * phi_ : Vec3{};
    f.spinRate = {};
  } else {
    // A unit vector across the start axis, carried to t (less the carry's round-off).
    const Vec3 e = carry(normalize(cross(u_, acrossHelper(u_))), 0, t);
    f.e1 = normalize(e - f.axis * dot(e, f.axis));
    f.spin = spin(t), f.spinRate = spinRate(t);
  }
  f.e2 = cross(f.axis, f.e1);
}

Vec3 PoseCurve::rotarySpin(double t) const {
  // R = A(t) B(t) with A = Rz(-C) and B = Ry(-B) or Rx(-A): Omega = Omega_A + A Omega_B.
  const double spin = machine_->spin0 + machine_->dSpin * clampUnit(t);
  const Vec3 tiltAxis = tableBC() ? Vec3{0, -machine_->dTilt, 0} : Vec3{-machine_->dTilt, 0, 0};
  return Vec3{0, 0, -machine_->dSpin} + rotZ(tiltAxis, -spin);
}

Vec3 PoseCurve::spinRate(double t) const {
  if (omega_ == 0 || kind_ == Kind::Slerp) return {};
  // d/dt (A Omega_B) = Omega_A x (A Omega_B); Omega_A is constant.
  const double spin = machine_->spin0 + machine_->dSpin * clampUnit(t);
  const Vec3 tiltAxis = tableBC() ? Vec3{0, -machine_->dTilt, 0} : Vec3{-machine_->dTilt, 0, 0};
  return cross(Vec3{0, 0, -machine_->dSpin}, rotZ(tiltAxis, -spin));
}

}  // namespace scallop
