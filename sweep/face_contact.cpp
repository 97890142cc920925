// The lowest point of a turning cutter's swept solid on a vertical line, where the line
// meets the flat bottom face.
//
// Notation as in swept_move.cpp: pose(t) = (tip(t), a(t)), t in [0, 1], the cutter
// turned rigidly about its tip with angular velocity Omega(t), |Omega| <= omega; K(t) the
// cutter at pose(t); l the vertical line through q = (x, y); f(t) the lowest point of
// K(t) on l, F = min over t of f(t).
//
//   1. The tip plane. Every point of a cutter lies at s >= 0 along its axis from the tip
//      (cutter.h), so K(t) lies in the half-space G_t(p) = a(t).(p - tip(t)) >= 0. Where
//      a_z(t) > 0, l crosses the plane G_t = 0 at
//          z_face(t) = tip_z - (a_x w_x + a_y w_y) / a_z,   w = (x, y) - tip_xy(t),
//      and every point of l below it is outside K(t): f(t) >= z_face(t), with equality
//      where the crossing lies in the bottom disc (|p - tip| <= Rb), a point of K(t).
//   2. Newton's method on z_face over [0, 1], in closed form. With N = a_xy.w and
//      D = a_z, z_face = tip_z - N / D, and (a' = Omega x a, a'' = Omega' x a + Omega x a',
//      w' = -tip'_xy, w'' = -tip''_xy)
//          N'  = a'_xy.w - a_xy.tip'_xy,
//          N'' = a''_xy.w - 2 a'_xy.tip'_xy - a_xy.tip''_xy,
//          (N/D)'  = (N' D - N D') / D^2,
//          (N/D)'' = (N'' D - N D'') / D^2 - 2 D' (N' D - N D') / D^3,
//      z_face' = tip'_z - (N/D)', z_face'' = tip''_z - (N/D)''. From t = 0.5 (so the
//      height is a function of the move and (x, y) alone) until Newton's decrement
//      z'^2 / (2 z'') is below 1e-10 mm, or at an end whose slope points out of [0, 1];
//      where z'' <= 0, straight to the end downhill.
//      The height returned, z* = z_face(t*), is attained where the crossing lies in the
//      disc (checked); otherwise this is no face contact and the caller goes on.
//   3. The proof: F >= z* - 1e-9. Let Q = (x, y, z* - 1e-9) and G(t) = a(t).(Q - tip(t)).
//      Where G(t) < 0 and a_z(t) > 0, Q and every point below it on l lie outside the
//      half-space of step 1, hence outside K(t): f(t) > Q_z. Taylor's theorem at t*,
//      tau = t - t*:
//          G(t) <= G + G' tau + (G'' + |G'''| w) tau^2 / 2,   w = max(t*, 1 - t*),
//          G'  = a'.(Q - tip) - a.tip',
//          G'' = a''.(Q - tip) - 2 a'.tip' - a.tip'',
//          |G'''| <= omega^3 D + 3 omega^2 S + 3 omega A + J
//      (|a^(k)| <= omega^k as for the certified search's cutter-fixed planes; D >=
//      |Q - tip(t)|, S, A, J bound |tip'|, |tip''|, |tip'''|), a quadratic in tau whose
//      maximum over [-t*, 1 - t*] is closed form: below zero, l is clear of every K(t)
//      below Q, and a_z(t) >= a_z(t*) - omega w > 0 is checked with it. At t* the face
//      passes through (x, y, z*), so G = -1e-9 a_z there, and G' ~ 0 at an interior
//      minimum: the bound holds wherever z_face curves up by more than the turn's third
//      derivative, one closed-form step for the whole move. This is the certified
//      search's Taylor form (its step 2d) with the plane of the face, whose support is
//      0; here no stationary search is needed to find the plane.
// Round-off: the proof keeps a slack of 1e-12 (1 + D) mm, far below the gap.
#include "sweep/face_contact.h"

#include <algorithm>
#include <cmath>

#include "sweep/certified_search.h"

namespace scallop {

namespace {

constexpr int kFaceNewtonSteps = 8;
constexpr double kFaceDecrementDone = 1e-10;  // mm, as for the rim contact
constexpr double kMinAxisZ = 1e-3;            // a steeper face is left to the certified search

// z_face and its first two derivatives at a pose (step 2); ok = false where the axis is
// too near the horizontal.
struct FaceHeight {
  bool ok = false;
  double z = 0, dz = 0, ddz = 0;
};

FaceHeight faceHeight(const PoseFrame& f, double x, double y) {
  FaceHeight out;
  const Vec3& a = f.axis;
  if (!(a.z > kMinAxisZ)) return out;
  const Vec3 a1 = cross(f.spin, a);
  const Vec3 a2 = cross(f.spinRate, a) + cross(f.spin, a1);
  const Vec3 &v = f.velocity, &acc = f.acceleration;
  const double wx = x - f.tip.x, wy = y - f.tip.y;
  const double N = a.x * wx + a.y * wy;
  const double N1 = a1.x * wx + a1.y * wy - (a.x * v.x + a.y * v.y);
  const double N2 =
      a2.x * wx + a2.y * wy - 2 * (a1.x * v.x + a1.y * v.y) - (a.x * acc.x + a.y * acc.y);
  const double D = a.z, D1 = a1.z, D2 = a2.z;
  const double cross1 = N1 * D - N * D1;
  out.ok = true;
  out.z = f.tip.z - N / D;
  out.dz = v.z - cross1 / (D * D);
  out.ddz = acc.z - ((N2 * D - N * D2) / (D * D) - 2 * D1 * cross1 / (D * D * D));
  return out;
}

// Step 3: whether the whole move stays above Q = (x, y, zQ) by the tip planes.
bool tipPlanesClear(const PoseCurve& curve, const PoseFrame& f, double x, double y, double zQ) {
  const double omega = curve.turnRate();
  const double S = curve.tipSpeedBound(), A = curve.tipAccelBound(), J = curve.tipJerkBound();
  const double w = std::max(f.t, 1 - f.t);
  if (!(f.axis.z - omega * w > 0)) return false;
  double D = 0;  // >= |Q - tip(t)| over the move
  for (const Vec3& e : {curve.tipStart(), curve.tipEnd()})
    D = std::max(D, std::hypot(x - e.x, y - e.y) + std::fabs(zQ - e.z));
  D += S;
  const Vec3& a = f.axis;
  const Vec3 a1 = cross(f.spin, a);
  const Vec3 a2 = cross(f.spinRate, a) + cross(f.spin, a1);
  const Vec3 u = Vec3{x, y, zQ} - f.tip;
  const double G0 = dot(a, u);
  const double G1 = dot(a1, u) - dot(a, f.velocity);
  const double G3 = omega * omega * omega * D + 3 * omega * omega * S + 3 * omega * A + J;
  const double M = dot(a2, u) - 2 * dot(a1, f.velocity) - dot(a, f.acceleration) + G3 * w;
  const double lo = -f.t, hi = 1 - f.t;
  auto P = [&](double tau) { return G0 + G1 * tau + 0.5 * M * tau * tau; };
  double top = std::max(P(lo), P(hi));
  if (M < 0) {
    const double peak = -G1 / M;
    if (peak > lo && peak < hi) top = std::max(top, G0 - 0.5 * G1 * G1 / M);
  }
  return top < -1e-12 * (1 + D);
}

}  // namespace

FaceContact locateFaceContact(const Cutter& cutter, const PoseCurve& curve, double x, double y) {
  FaceContact out;
  const double rb = cutter.bottomRadius();
  if (cutter.general() || !(rb > 0)) return out;
  double t = 0.5;
  for (int step = 0; step < kFaceNewtonSteps; ++step) {
    const PoseFrame f = curve.frame(t);
    const FaceHeight h = faceHeight(f, x, y);
    if (!h.ok) return out;
    const bool atEnd = (t <= 0 && h.dz > 0) || (t >= 1 && h.dz < 0);
    double dt = 0;
    if (!atEnd) {
      // Where z_face does not curve up (a leaning face fed straight is nearly linear in
      // t), downhill to the end: the proof decides whether the minimum is there.
      const double next = h.ddz > 0 ? t - h.dz / h.ddz : (h.dz > 0 ? 0.0 : 1.0);
      dt = std::clamp(next, 0.0, 1.0) - t;
    }
    if (atEnd || -0.5 * h.dz * dt <= kFaceDecrementDone) {
      // Step 2's check that the crossing is a point of K(t) (in the bottom disc), then
      // step 3's proof.
      const Vec3 p = Vec3{x, y, h.z} - f.tip;
      if (!(dot(p, p) <= rb * rb)) return out;
      if (!tipPlanesClear(curve, f, x, y, h.z - kProofGap)) return out;
      out.found = true;
      out.t = t, out.z = h.z, out.normal = -f.axis;
      return out;
    }
    t += dt;
  }
  return out;
}

}  // namespace scallop
