// The tip-plane bound of a move.
//
// Notation as in pose_curve.h and swept_move.cpp: tip(t), the unit axis a(t), the turn
// rate omega with |a'| <= omega and |a''| <= omega^2 (a is a cutter-fixed direction), S
// >= |tip'| and A >= |tip''| over [0, 1] (S = |p1 - p0|, A = 0 for a linear tip).
//
//   1. Every cutter K = (C (+) Ball(r)) n {s <= L} has s = a.(p - tip) >= 0 at each of
//      its points (cutter.h: the core starts at s = r), so a point Q of the line lies
//      in K(t) only if G(t) = a(t).(Q - tip(t)) >= 0.
//   2. G'' = a''.(Q - tip) - 2 a'.tip' - a.tip'', so |G''| <= E = omega^2 D + 2 omega S + A
//      with D >= |Q - tip(t)|, and G lies below its chord plus E t (1 - t) / 2:
//          G(t) <= max(G(0), G(1)) + E / 8.
//   3. At an end, G(i) = a_z(i) (z - h_i) with h_i the height of the tip plane over
//      (x, y): h_i = tip_i.z - (a_i.x (x - tip_i.x) + a_i.y (y - tip_i.y)) / a_i.z.
//      So at z = B = min over i of (h_i - E / (8 a_z(i))) both G(i) <= -E / 8, and
//      G(t) <= 0 for every t: Q = (x, y, B) is below every tip plane.
//   4. Below B too: where a_z(t) > 0, G falls as z falls (dG/dz = a_z(t)). By the
//      Lipschitz bound, a_z(t) >= max(a_z(0) - omega t, a_z(1) - omega (1 - t)) >=
//      (a_z(0) + a_z(1) - omega) / 2, positive when checked. So no K(t) reaches the line
//      at or below B (up to the round-off kept below): every height is >= B.
//   D is needed at z = B only (step 4 uses monotonicity, not E, below it). tip(t) lies
//   within S / 2 of an end, and B lies below min h_i by at most E / (8 min a_z), checked
//   to be <= 1 mm, so D = max_i |Q - tip_i| + S / 2 + 1 with Q at z = min h_i. Over a
//   rectangle, |Q - tip_i|'s horizontal part and |h_j - tip_i.z| are convex in (x, y),
//   so their largest values are at its corners.
#include "sweep/tip_plane_bound.h"

#include <algorithm>

namespace scallop {

double TipPlaneBound::minOver(double x0, double y0, double x1, double y1) const {
  double low = HUGE_VAL;
  for (int i = 0; i < 2; ++i)
    low = std::min(low, a[i] + std::min(b[i] * x0, b[i] * x1) + std::min(c[i] * y0, c[i] * y1));
  return low;
}

TipPlaneBound tipPlaneBound(const PoseCurve& curve, double x0, double y0, double x1, double y1) {
  TipPlaneBound out;
  const double omega = curve.turnRate();
  const Vec3 tip[2] = {curve.tipStart(), curve.tipEnd()};
  const Vec3 axis[2] = {curve.axis(0), curve.axis(1)};  // the ends: no trigonometry
  // Step 4's condition (which also keeps both ends' planes from turning vertical).
  if (!(axis[0].z > 0 && axis[1].z > 0 && axis[0].z + axis[1].z > omega + 1e-9)) return out;
  // h_i = a + b x + c y (step 3).
  double a[2], b[2], c[2];
  for (int i = 0; i < 2; ++i) {
    b[i] = -axis[i].x / axis[i].z, c[i] = -axis[i].y / axis[i].z;
    a[i] = tip[i].z - b[i] * tip[i].x - c[i] * tip[i].y;
  }
  // D over the rectangle, from its corners.
  const double S = curve.tipSpeedBound();
  double D = 0;
  for (int i = 0; i < 2; ++i) {
    double horizontal2 = 0, vertical = 0;  // (D has a millimetre to spare: no hypot)
    for (const double x : {x0, x1}) {
      for (const double y : {y0, y1}) {
        const double dx = x - tip[i].x, dy = y - tip[i].y;
        horizontal2 = std::max(horizontal2, dx * dx + dy * dy);
        for (int j = 0; j < 2; ++j)
          vertical = std::max(vertical, std::fabs(a[j] + b[j] * x + c[j] * y - tip[i].z));
      }
    }
    D = std::max(D, std::sqrt(horizontal2 + vertical * vertical));
  }
  D += 0.5 * S + 1;
  // A along the axis (constant where an arc's tip'' is smaller along it).
  const double E = omega * omega * D + 2 * omega * S + curve.tipAccelAlong(axis[0]);
  if (!(E / (8 * std::min(axis[0].z, axis[1].z)) <= 1)) return out;
  for (int i = 0; i < 2; ++i) {
    // The margin of step 3, and the round-off of the few products here (each well
    // below 1e-15 relative; the caller keeps its own for evaluating the planes).
    const double margin = E / (8 * axis[i].z);
    out.a[i] = a[i] - margin - 1e-12 * (1 + std::fabs(a[i]) + D) / axis[i].z;
    out.b[i] = b[i], out.c[i] = c[i];
  }
  return out;
}

}  // namespace scallop
