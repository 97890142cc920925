// Step 2 of the certified search (certified_search.cpp): lower bounds of f over an
// interval I = [ta, tb], w = tb - ta, each proven.
//
// Notation as in swept_move.cpp: pose(t) = (tip(t), axis(t)), t in [0, 1], K(t) the
// cutter at pose(t), f(t) its lowest point on the vertical line l through q = (x, y).
//
//   2a. World-fixed plane (the chord bound). For a unit N with N.z < 0 and
//      h_t(N) = max over K(t) of N.p, every point of K(t) on l has N.p <= h_t(N), so
//      f(t) >= (h_t(N) - N.x x - N.y y) / N.z, and H >= max over I of h_t(N) bounds f
//      on I. A cutter point k (tip at the origin) follows g(t) = N.(tip(t) + R(t) k)
//      with |R''k| <= omega^2 |k| and |tip''| <= A (0 for a linear tip; an arc's
//      constant axis has omega = 0 but A > 0), so g lies below its chord plus
//      (omega^2 |k| + A) w^2 / 8 (interpolation error of a function with bounded second
//      derivative):  H = max(h_ta(N), h_tb(N)) + (omega^2 rho + A) w^2 / 8, rho bounding |k|
//      over the points that can attain the support during I: each g moves by at most
//      V w, V = |N.(p1 - p0)| + omega reach, so those points lie in the cap
//      N.k >= h - 2 V w of K(ta), below s_max = (|N_perp| R + 2 V w - h) / (-N.a) along
//      the axis: rho = hypot(s_max, R) (the flute top drops out). N is the normal at
//      the lowest point of K(ta) or K(tb) on l, or, where l misses K or meets its side,
//      a steep plane leaning out of the footprint.
//   2b. Cutter-fixed plane. The tangent plane at the lowest point of K(tS) on l, carried
//      with the cutter: N(t) = R(t) R(tS)^-1 N_S, h = h_tS(N_S) for all t (the cutter
//      turns rigidly), so K(t) lies in N(t).(p - tip(t)) <= h, and a height z is below
//      every K(t) of I if g(t) = N(t).(Q - tip(t)) - h > 0 on I, Q = (x, y, z) (with
//      N.z(t) < 0 on I, g falls as z rises). Its derivatives are in closed form (see
//      cutterPlane), and g >= chord - max(0, sup g'') w^2 / 8 >= min(g(ta), g(tb))
//      less that margin: only curvature towards the line costs. Where the line meets
//      a flat face (the bottom of a bull or flat cutter) this plane is the face itself
//      and the bound is exact; 2a's fixed normal there loses the rim's rotation at
//      first order.
//   2c. Grown cutter. Every point of every K(t), t in I, lies within
//      grow = (|p1 - p0| + omega reach) w / 2 of its place at the middle pose, so the
//      lowest point of that cutter grown by `grow` (R, r + grow, L + 2 grow, tip grow
//      lower) bounds f on I, and a line that misses it misses every K(t). Used where l
//      leaves or grazes a cutter, where planes say little.
//   2d. Taylor form of 2b at a sample: g(t) >= g + g' tau + m tau^2 / 2 with m the
//      second derivative at the sample less |g'''| w. Where g curves away from the
//      line (m > 0) and the sample is a minimum of f (g' ~ 0), this proves both
//      intervals beside it at once, however wide.
//   2e. Flute top (a miss). 2c and the ray clearance see the flank as if it went on above
//      the flute top; near the t where the line first touches the top's rim they lose
//      V w / 2 (first order) and prove only intervals shrinking with their distance from
//      it. Two cutter-fixed planes that contain every cutter, its top's and one of its
//      flank's, each proven positive at one height by 2d, show the line misses: the
//      derivation is at missesBesideFluteTop.
#include "sweep/interval_bounds.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "sweep/profile_lowest_point.h"

namespace scallop {

namespace {

TipMotionBounds tipMotionOf(const PoseCurve& curve, double speed) {
  return {curve.tipEnd() - curve.tipStart(),
          curve.linearTip(),
          speed,
          curve.tipAccelBound(),
          curve.tipJerkBound(),
          curve.arcTip() ? &curve : nullptr};
}

// The chord bound of step 2a: H >= max over [a.t, b.t] of h_t(N), N unit, given the
// supports hKa, hKb of the cutters at the two poses (tip at the origin) in N.
inline double supportOver(const Cutter& c, double omega, double reach, const TipMotionBounds& tip,
                          const SearchSample& a, double hKa, const SearchSample& b, double hKb,
                          const Vec3& N) {
  const double h = std::max(dot(N, a.tip) + hKa, dot(N, b.tip) + hKb);
  const double w = b.t - a.t;
  const double accel = tip.accelAlong(N);
  if ((omega == 0 && accel == 0) || w <= 0) return h;
  // The cap of the points that can attain the support during the interval.
  const double V = tip.rateAlong(N) + omega * reach;
  const double u = dot(N, a.axis);
  double rho = reach;
  if (u < 0) {
    const double nPerp = std::sqrt(std::max(0.0, 1 - u * u));
    const double sMax = (nPerp * c.radius + 2 * V * w - hKa) / -u;
    const double s = std::clamp(sMax, 0.0, c.fluteLength);
    rho = std::min(reach, std::sqrt(s * s + c.radius * c.radius));
  }
  return h + (omega * omega * rho + accel) * w * w / 8;
}

}  // namespace

Vec3 steepNormal(const Cutter& c, const Vec3& tip, const Vec3& a, double x, double y) {
  const double ex = a.x * c.fluteLength, ey = a.y * c.fluteLength, ee = ex * ex + ey * ey;
  const double px = x - tip.x, py = y - tip.y;
  const double s = ee > 0 ? std::clamp((px * ex + py * ey) / ee, 0.0, 1.0) : 0.0;
  const double dx = px - s * ex, dy = py - s * ey, dd = std::sqrt(dx * dx + dy * dy);
  if (!(dd > 1e-9)) return {};
  return normalize(Vec3{dx / dd, dy / dd, -1e-3});
}

double turningSupport(const Cutter& cutter, const PoseCurve& curve, const TurningBounds& bounds,
                      const Vec3& N) {
  SearchSample a, b;
  a.t = 0, a.tip = curve.tip(0), a.axis = curve.axis(0);
  b.t = 1, b.tip = curve.tip(1), b.axis = curve.axis(1);
  return supportOver(cutter, curve.turnRate(), bounds.reach, tipMotionOf(curve, bounds.tipSpeed), a,
                     dot(N, cutterSupport(cutter, a.axis, N)), b,
                     dot(N, cutterSupport(cutter, b.axis, N)), N);
}

IntervalBounds::IntervalBounds(const Cutter& cutter, const PoseCurve& curve,
                               const TurningBounds& bounds, double x, double y)
    : c_(cutter),
      curve_(curve),
      bounds_(bounds),
      x_(x),
      y_(y),
      omega_(curve.turnRate()),
      tip_(tipMotionOf(curve, bounds.tipSpeed)) {}

double IntervalBounds::worldPlane(const SearchSample& from, const SearchSample& a,
                                  const SearchSample& b) const {
  const Vec3& N = from.normal;
  if (N.z == 0) return -HUGE_VAL;
  const SearchSample& other = &from == &a ? b : a;
  const double hOther = dot(N, cutterSupport(c_, other.axis, N));
  const double H = &from == &a
                       ? supportOver(c_, omega_, bounds_.reach, tip_, a, from.hOwn, b, hOther, N)
                       : supportOver(c_, omega_, bounds_.reach, tip_, a, hOther, b, from.hOwn, N);
  const double nq = N.x * x_ + N.y * y_;
  const double z = (H - nq) / N.z;
  return z - 1e-12 * (1 + std::fabs(H) + std::fabs(nq)) / -N.z;
}

// Steps 2b and 2d share the plane fixed to the cutter at a sample S and its
// derivatives: g(t) = N(t).(Q - tip(t)) - h_S with N(t) = R(t) R(tS)^-1 N_S, so that
//   g'  = N'.(Q - tip) - N.tip',                N'  = Omega x N,
//   g'' = N''.(Q - tip) - 2 N'.tip' - N.tip'',  N'' = Omega' x N + Omega x (Omega x N),
// and |g'''| <= omega^3 D + 3 omega^2 S + 3 omega A + J (|N^(k)| <= omega^k, D >=
// |Q - tip|, S, A, J >= |tip'|, |tip''|, |tip'''|; A = J = 0 for a linear tip). This is
// that bound of |g'''|; tip_.speed also bounds the tip's path length, mm. J is
// |N . tip'''|'s bound for the sample's N: N(t) = N where the axis is constant (omega
// = 0, the arcs, the only kind where it is less than J), and J for every N otherwise.
double IntervalBounds::thirdDerivative(double D, const Vec3& N) const {
  const double move = tip_.speed;
  return omega_ * omega_ * omega_ * D + 3 * omega_ * omega_ * move + 3 * omega_ * tip_.accel +
         tip_.jerkAlong(N);
}

// D of steps 2b and 2d: >= |Q - tip(t)| for t in [a.t, b.t] and Q.z in [zLow, zHigh].
double IntervalBounds::distanceBound(const SearchSample& a, const SearchSample& b, double zLow,
                                     double zHigh) const {
  double D = 0;
  for (const SearchSample* e : {&a, &b})
    D = std::max(D,
                 std::sqrt((x_ - e->tip.x) * (x_ - e->tip.x) + (y_ - e->tip.y) * (y_ - e->tip.y)) +
                     std::max(std::fabs(zHigh - e->tip.z), std::fabs(zLow - e->tip.z)));
  return D + tip_.speed;
}

// g >= its chord - max(0, sup g'') w^2 / 8 (only curvature towards the line costs: a
// concave g lies above its chord), and the chord >= the smaller end value; each end's
// g >= margin moves the plane up by the margin. The heights where this is claimed are
// [lowest tip - reach, U]: Q's z enters g'' and D there.
double IntervalBounds::cutterPlane(const SearchSample& from, const SearchSample& to,
                                   const SearchSample& a, const SearchSample& b, double U) const {
  const Vec3& Na = from.normal;
  if (!(from.z < HUGE_VAL) || !(Na.z <= -1e-3) || !(U < HUGE_VAL)) return -HUGE_VAL;
  const Vec3 Nb = curve_.carry(Na, from.t, to.t);
  const double w = b.t - a.t;
  if (std::max(Na.z, Nb.z) + omega_ * w >= 0) return -HUGE_VAL;  // may turn horizontal
  const double h = from.hOwn;
  const double floor = std::min(a.tip.z, b.tip.z) - bounds_.reach;
  const double D = distanceBound(a, b, floor, U);
  const double cross2 = 2 * dot(from.dn, from.vel) + dot(Na, from.acc);
  double gpp = -HUGE_VAL;  // sup of g'' over the interval and those heights
  for (double z : {floor, U})
    gpp = std::max(gpp, dot(from.ddn, Vec3{x_, y_, z} - from.tip) - cross2);
  gpp += thirdDerivative(D, Na) * w;
  const double margin = std::max(0.0, gpp) * w * w / 8;
  auto planeZ = [&](const Vec3& N, const SearchSample& e) {
    const double nq = N.x * (x_ - e.tip.x) + N.y * (y_ - e.tip.y);
    return e.tip.z + (margin + h - nq) / N.z;
  };
  const double z0 = std::min({planeZ(Na, from), planeZ(Nb, to), U});
  return std::max(z0, floor) - 1e-12 * (1 + std::fabs(z0) + D) / -std::max(Na.z, Nb.z);
}

// |dp/dt| of any cutter point: the tip's speed plus omega reach. On a curved tip the
// interval's own speed bound, |tip'(tc)| + A w / 2, is tighter than the move's.
double IntervalBounds::grownCutter(const SearchSample& a, const SearchSample& b) const {
  const double tc = 0.5 * (a.t + b.t), w = b.t - a.t;
  const double move = tip_.speed;
  const double tipSpeed =
      tip_.linear ? move : std::min(move, length(curve_.tipVelocity(tc)) + 0.5 * tip_.accel * w);
  const double speed = tipSpeed + omega_ * bounds_.reach;
  const double grow = speed * 0.5 * w * (1 + 1e-12) + 1e-12;
  const Vec3 axis = curve_.axis(tc), tip = curve_.tip(tc) - axis * grow;
  // K (+) Ball(grow) lies in the cutter with R, r grown by `grow` and L by twice that,
  // whose tip is `grow` lower along the axis (the same core, swept a ball wider); for a
  // general cutter it is the grown profile (CutterProfile::grown), in the same frame.
  LowestPoint lp;
  if (c_.general()) {
    lp = profileLowestPoint(c_.profile->grown(grow), axis, x_ - tip.x, y_ - tip.y);
  } else {
    Cutter grown = c_;
    grown.radius += grow, grown.cornerRadius += grow, grown.fluteLength += 2 * grow;
    lp = cutterLowestPoint(grown, axis, x_ - tip.x, y_ - tip.y);
  }
  if (!lp.hit) return HUGE_VAL;
  return lp.z + tip.z - 1e-12 * (1 + std::fabs(lp.z) + std::fabs(tip.z));
}

// g(t) >= g + g' tau + m tau^2 / 2 with m = g''(tS) - |g'''| w, whose minimum over tau
// is closed form. Where g curves away from the line (m > 0: the convex case that costs
// step 2b its margin) this proves a whole interval from one sample at a minimum of f,
// where g' ~ 0.
bool IntervalBounds::taylorProves(const SearchSample& from, const SearchSample& a,
                                  const SearchSample& b, double z) const {
  const Vec3& N = from.normal;
  if (!(from.z < HUGE_VAL) || !(N.z <= -1e-3)) return false;
  const double w = b.t - a.t;
  if (std::max(N.z, curve_.carry(N, from.t, from.t == a.t ? b.t : a.t).z) + omega_ * w >= 0)
    return false;
  return carriedPlanePositive(from, a, b, z);
}

// The Taylor form of 2d for any unit N carried with the cutter from `from` (normal, hOwn,
// dn, ddn set): whether g(t) = N(t).(Q - tip(t)) - hOwn > 0 on [a.t, b.t], Q = (x, y, z).
bool IntervalBounds::carriedPlanePositive(const SearchSample& from, const SearchSample& a,
                                          const SearchSample& b, double z) const {
  const Vec3& N = from.normal;
  const double w = b.t - a.t;
  const Vec3 q = Vec3{x_, y_, z} - from.tip;
  const double g0 = dot(N, q) - from.hOwn, g1 = dot(from.dn, q) - dot(N, from.vel);
  const double D = distanceBound(a, b, z, z);
  const double m =
      dot(from.ddn, q) - 2 * dot(from.dn, from.vel) - dot(N, from.acc) - thirdDerivative(D, N) * w;
  const double ta = a.t - from.t, tb = b.t - from.t;
  double low = std::min(g0 + g1 * ta + 0.5 * m * ta * ta, g0 + g1 * tb + 0.5 * m * tb * tb);
  if (m > 0 && -g1 / m > ta && -g1 / m < tb) low = std::min(low, g0 - 0.5 * g1 * g1 / m);
  return low > 1e-13 * (1 + D);
}

// Step 2e. Every cutter lies in {a.(p - tip) <= L} (below its flute top) and, for any
// unit n across its axis, in {n.(p - tip) <= R} (its flank's cylinder), both carried
// with the cutter. Where, at the middle tc of I, the line crosses the top's plane
// outside the flank (rho > R there) and n, the direction across the axis to that
// crossing, points down (n.z < 0), pick h between the crossing and the height where
// the line leaves n's half-space. If for every t in I both
//     g_top(t) = a(t).(Q - tip(t)) - L > 0  and  g_flank(t) = n(t).(Q - tip(t)) - R > 0
// for Q = (x, y, h), with a_z > 0 and n_z < 0 over I (each within omega w of its value
// at tc), then the line's points at z >= h lie above the top (a.(Q(z) - tip) grows with
// z) and those at z <= h outside the flank (n.(Q(z) - tip) falls as z rises): the line
// misses K(t). Each g is the cutter-fixed plane of 2b/2d with N = a, h = L or N = n,
// h = R, proven by 2d's Taylor form at tc: first order exact, so that near the t where
// the line first touches the top's rim the intervals it proves shrink only with the
// square root of their distance from it, where the grown cutter's (first order) shrink
// in proportion, and the search ran out of samples there.
bool IntervalBounds::missesBesideFluteTop(const SearchSample& a, const SearchSample& b) const {
  if (c_.general()) return false;
  const double w = b.t - a.t, tc = 0.5 * (a.t + b.t);
  SearchSample m;
  m.t = tc, m.tip = curve_.tip(tc), m.axis = curve_.axis(tc);
  m.vel = curve_.tipVelocity(tc), m.acc = curve_.tipAcceleration(tc);
  const Vec3& axis = m.axis;
  if (!(w > 0) || !(axis.z - omega_ * w > 0)) return false;
  const double L = c_.fluteLength, R = c_.radius;
  const double wx = x_ - m.tip.x, wy = y_ - m.tip.y;
  const Vec3 atTop{wx, wy, (L - axis.x * wx - axis.y * wy) / axis.z};  // from the tip
  const Vec3 across = atTop - axis * dot(atTop, axis);
  const double rho = length(across);
  if (!(rho > R)) return false;
  const Vec3 n = across / rho;
  if (!(n.z + omega_ * w < 0)) return false;
  const double zFlank = (R - n.x * wx - n.y * wy) / n.z;  // above atTop.z: rho > R
  const double h = m.tip.z + 0.5 * (atTop.z + zFlank);
  const Vec3 spin = curve_.spin(tc), spinRate = curve_.spinRate(tc);
  for (const auto& plane : {std::make_pair(axis, L), std::make_pair(n, R)}) {
    m.normal = plane.first, m.hOwn = plane.second;
    m.dn = cross(spin, m.normal);
    m.ddn = cross(spinRate, m.normal) + cross(spin, m.dn);
    if (!carriedPlanePositive(m, a, b, h)) return false;
  }
  return true;
}

}  // namespace scallop
