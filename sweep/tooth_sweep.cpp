// The lowest point at which a cutting edge crosses a vertical line (tooth_sweep.h).
//
// The crossing condition, one equation in t. At time t the cutter stands at its pose,
// displaced by the runout (the cutter's own tip T(t) = tip(t) + runout u(psi_r - phi)).
// The vertical line through (x, y) enters the convex cutter at its lowest point E(t)
// (cutterLowestPoint) and leaves it at its highest X(t) (the lowest point of the cutter
// mirrored in z). A point of the cutter's surface lies on an edge exactly when its
// body angle is an edge's: with E - T = h a + rho (cos theta e1 + sin theta e2),
//     F(t) = flutes (theta(t) + phi(t) - h(t) tan(beta) / R - lambda(rho(t), h(t))) / (2 pi)
// is an integer (tooth k = F mod flutes), lambda the rake's lag (RakeLag, zero without
// rake; a raked edge stays on the profile's surface of revolution, at the angle that
// puts it on its rake face, so every other argument here holds as it is). So the edges
// cross the line where F(t) is an integer, at the heights E(t).z, and where the same
// function of X(t) is one, at X(t).z; the top cap (h = L) carries no edge. Every
// crossing of the line with an edge is one of these: an edge lies on the cutter's
// boundary, and the line meets the boundary only at E and X (or, where it runs along a
// face, in a segment whose lowest point is E).
//
// Finding every root. phi turns at phaseRate (rad per unit t), 2 pi / flutes in one
// tooth period; theta and h move with the line's motion relative to the cutter, slowly
// except near the cutter's axis (theta turns fast; every edge meets there) and the
// silhouette (E and X meet). F is sampled a quarter tooth period apart; an interval on
// which the point's own turn (theta less the edge's lag) exceeds half of the spindle's,
// or whose ends meet different faces, is halved. On the intervals left F is monotone,
// so its integers between the end values are all its roots; each is solved by bracketed
// regula falsi until F's residual times dz/dF is below 1e-13 mm. Halving stops at
// leaves of 1/256 of a tooth period where the faces agree (the point sweeping round
// near the axis, where F's end values show the crossing the sweep makes), and a search
// has a budget of halvings past which it counts as unproven.
//
// Per-tooth geometry. Teeth with their own offsets lie on their own solids (the profile
// moved out by dr, the tip lowered by da): teeth with equal offsets form a group, each
// group is searched as described here on its own solid for the F values of its teeth
// (F - flutes psi_k / (2 pi) a multiple of flutes; every integer for one group of every
// tooth at equal pitch), and the groups share the best crossing. Teeth whose edges
// cover a span of the profile only (inserts) are grouped by their span too, and a
// piercing point off the span carries no edge, as the top cap carries none.
//
// Which intervals matter. Every edge point lies in the spindle envelope (the solid of
// revolution holding the cutter at every spindle angle), so a crossing at t is no lower
// than the envelope's lowest point h(t) at pose(t). For a constant axis, h is convex in
// t (the cutter translates linearly: {(t, z) : (x, y, z) - tip(t) in K} is convex), its
// minimum is the swept envelope's height at t*, and a subgradient h'(t) = (n . v) / n_z
// (n its normal, v the tip velocity) gives tangent lines below it. So:
//   * the scan starts at t* and runs outward, stopping where h >= the best crossing;
//   * an interval is solved only where the tangent lines at its ends allow a height
//     below the best;
//   * exit points are skipped over an interval where a solid inside every cutter of it
//     (exitBound) lies above the best.
// A turning move's h is not convex; its whole [0, 1] is scanned and an interval is
// skipped only when ray clearance proves the envelope above the best over it
// (ray_clearance.h). The result is the least crossing height: the pruning only drops
// crossings no lower than one already found, so the height is a function of
// (move, x, y) alone.
#include "sweep/tooth_sweep.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/ray_clearance.h"
#include "sweep/tooth_groups.h"

namespace scallop {

namespace {

constexpr double kTwoPi = 2 * kPi;
// Smallest interval (in t) that is still halved: below it the line passes through the
// cutter's axis (every edge meets there) or its silhouette within ~1e-13 of a move.
constexpr double kMinInterval = 1e-13;
constexpr int kMaxDepth = 48;
constexpr int kSolveSteps = 80;
// The scan step, in tooth periods: F moves by about this much between samples.
constexpr double kStepPeriods = 0.25;
// Halvings one search may make. Where F's spindle term does not dominate over a whole
// stretch (a slow spindle against a fast sweep of the piercing point), halving does not
// make it so; past this budget such a search counts as unproven (unprovenSearches()).
constexpr int kMaxSplits = 4096;

std::atomic<unsigned long long> unprovenCrossingCount{0};

double wrapAngle(double a) {  // to [-pi, pi] (the differences wrapped are below 4 pi)
  while (a > kPi) a -= kTwoPi;
  while (a < -kPi) a += kTwoPi;
  return a;
}

// e1 of the spindle frame at axis a: world X made perpendicular to a, or world Y when a
// is within 30 degrees of X.
Vec3 referenceAcross(const Vec3& a) {
  const Vec3 ref = std::abs(a.x) > 0.8660254037844386 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  return normalize(ref - dot(ref, a) * a);
}

Vec3 mirrorZ(const Vec3& v) {
  return {v.x, v.y, -v.z};
}

}  // namespace

// The crossing function at t, evaluated lazily: the pose first, then the spindle
// envelope's lowest point and each side (0 the entry point, 1 the exit point) when an
// interval needs them.
struct ToothSweep::Sample {
  double t = 0;
  double phi = 0;
  Vec3 a, e1, e2;  // the spindle frame at t
  Vec3 tip, T;     // the spindle's tip and the cutter's own (with the runout), mm
  bool envDone = false;
  bool envHit = false;      // the line meets the spindle envelope at pose(t)
  double envZ = 0;          // h(t), mm
  double envSlope = 0;      // a subgradient dh/dt (constant axis only), mm per unit t
  bool slopeKnown = false;  // false where the normal is (nearly) horizontal
  Vec3 envNormal;
  bool done[2] = {false, false};
  bool hit[2] = {false, false};  // the line meets the cutter at an edge-bearing face
  bool off[2] = {false, false};  // it meets the solid off the teeth's edge span (z, theta, h set)
  double z[2] = {0, 0};          // E(t).z, X(t).z, mm
  // Their angles from e1, (-pi, pi], less the rake's lag of an edge point there (RakeLag;
  // F takes the angle and the lag only as theta - lambda).
  double theta[2] = {0, 0};
  double h[2] = {0, 0};  // their heights above the tip along the axis, mm
  Vec3 normal0;          // the entry point's normal
};

ToothSweep::ToothSweep(const Cutter& cutter, const PoseCurve& curve, double phaseStart,
                       double phaseRate, bool counterClockwise, const Mirror* mirror)
    : cutter_(cutter),
      envelope_(cutter.spindleEnvelope()),
      curve_(counterClockwise && mirror ? mirror->curve : curve),
      phaseStart_(phaseStart),
      phaseRate_(phaseRate),
      ccw_(counterClockwise && !mirror),
      mirrored_(counterClockwise && mirror) {
  if (mirrored_) mirroredEnvelope_ = mirror->envelope;
  axisStart_ = curve_.axis(0);
  e1Start_ = referenceAcross(axisStart_);
  e2Start_ = ccw_ ? cross(e1Start_, axisStart_) : cross(axisStart_, e1Start_);
  helixSlope_ = std::tan(degToRad(cutter_.teeth.helixDeg)) / cutter_.radius;
  runoutPhase_ = degToRad(cutter_.teeth.runoutPhaseDeg);
  tipSpeed_ = curve_.tipSpeedBound();
  translates_ = curve_.constantAxis() && curve_.linearTip();
  vertical_ = translates_ && axisStart_.x == 0 && axisStart_.y == 0 && axisStart_.z == 1;
  drop_ = cutter_.teeth.axialReach();
  if (drop_ > 0 && !translates_)
    throw InputError("tool.tooth_offsets",
                     "a tooth reaching below the tip (axial offset > 0) needs straight moves "
                     "with a constant tool axis");
  double offsetReach = 0;
  for (const ToothOffset& o : cutter_.teeth.toothOffsets())
    offsetReach = std::max(offsetReach, std::abs(o.radial) + std::abs(o.axial));
  reach_ = std::hypot(cutter_.fluteLength, cutter_.radius) + cutter_.teeth.runout + offsetReach;
  groups_ = makeToothGroups(cutter_, kStepPeriods * kTwoPi / (cutter_.teeth.flutes * phaseRate_));
}

unsigned long long ToothSweep::unprovenSearches() {
  return unprovenCrossingCount.load();
}

void ToothSweep::frame(double t, Vec3& a, Vec3& e1, Vec3& e2) const {
  if (curve_.constantAxis()) {
    a = axisStart_, e1 = e1Start_, e2 = e2Start_;
    return;
  }
  a = curve_.axis(t);
  e1 = curve_.carry(e1Start_, 0, t);
  e1 = normalize(e1 - dot(e1, a) * a);
  e2 = ccw_ ? cross(e1, a) : cross(a, e1);
}

Vec3 ToothSweep::edgePoint(int k, double h, double rho, double t) const {
  if (mirrored_) {
    ToothSweep cw = *this;
    cw.mirrored_ = false;
    const Vec3 p = cw.edgePoint(k, h, rho, t);
    return {p.x, -p.y, p.z};
  }
  Vec3 a, e1, e2;
  frame(t, a, e1, e2);
  const double phi = phaseStart_ + phaseRate_ * t;
  if (rho < 0 && cutter_.general()) {
    rho = cutter_.profile->width(h);  // the chain's radius at height h
  } else if (rho < 0) {
    const double r = cutter_.cornerRadius, rb = cutter_.bottomRadius();
    rho = h >= r ? cutter_.radius : rb + std::sqrt(std::max(0.0, r * r - (r - h) * (r - h)));
  }
  const RakeLag rake = cutter_.rakeLag(k);
  const double psi = cutter_.teeth.toothAngle(k) + h * helixSlope_ + rake(rho, h) - phi;
  const double psiR = runoutPhase_ - phi;
  const ToothOffset o = cutter_.teeth.toothOffset(k);
  return curve_.tip(t) + cutter_.teeth.runout * (std::cos(psiR) * e1 + std::sin(psiR) * e2) +
         (rho + o.radial) * (std::cos(psi) * e1 + std::sin(psi) * e2) + (h - o.axial) * a;
}

ToothSweep::Sample ToothSweep::pose(double t) const {
  Sample s;
  s.t = t;
  s.phi = phaseStart_ + phaseRate_ * t;
  frame(t, s.a, s.e1, s.e2);
  s.tip = curve_.tip(t);
  s.T = s.tip;
  if (cutter_.teeth.runout > 0) {
    const double psiR = runoutPhase_ - s.phi;
    s.T = s.T + cutter_.teeth.runout * (std::cos(psiR) * s.e1 + std::sin(psiR) * s.e2);
  }
  return s;
}

// A proven lower bound of h(t) from a sample's tangent line (h is convex in t for a
// constant axis), which lets the stationary search start just below its answer.
double ToothSweep::tangentBelow(const Sample* ref, double t) const {
  if (!ref || !translates_ || !ref->envDone || !ref->envHit || !ref->slopeKnown) return -HUGE_VAL;
  const double z = ref->envZ + ref->envSlope * (t - ref->t);
  return z - 1e-9 * (1 + std::abs(z));
}

void ToothSweep::needEnvelope(const Group& g, Sample& s, double x, double y, const Sample* near1,
                              const Sample* near2) const {
  if (s.envDone) return;
  s.envDone = true;
  const double below = std::max(tangentBelow(near1, s.t), tangentBelow(near2, s.t));
  const Vec3 tip = g.drop != 0 ? s.tip - g.drop * s.a : s.tip;
  const LowestPoint env = cutterLowestPoint(g.envelope, s.a, x - tip.x, y - tip.y, below - tip.z);
  s.envHit = env.hit;
  if (!env.hit) return;
  s.envZ = env.z + tip.z;
  s.envNormal = env.normal;
  if (env.normal.z < -1e-9) {
    s.envSlope = dot(env.normal, curve_.tipVelocity(s.t)) / env.normal.z;
    s.slopeKnown = true;
  }
}

void ToothSweep::needSide(const Group& g, Sample& s, int side, double x, double y,
                          const Sample* near1, const Sample* near2) const {
  if (s.done[side]) return;
  s.done[side] = true;
  // The group's own tip (the cutter's, lowered by the teeth's axial offset).
  const Vec3 T = g.drop != 0 ? s.T - g.drop * s.a : s.T;
  LowestPoint lp;
  if (side == 0 && cutter_.teeth.runout <= 0) {
    // Without runout the group's solid is its own spindle envelope.
    needEnvelope(g, s, x, y, near1, near2);
    lp.hit = s.envHit;
    lp.z = s.envZ - T.z;
    lp.normal = s.envNormal;
  } else if (side == 0) {
    lp = cutterLowestPoint(g.cutter, s.a, x - T.x, y - T.y);
  } else {
    // The exit point: the lowest point of the cutter mirrored in z (tip at the origin).
    lp = cutterLowestPoint(g.cutter, mirrorZ(s.a), x - T.x, y - T.y);
    lp.z = -lp.z;
  }
  if (!lp.hit) return;
  const Vec3 q{x - T.x, y - T.y, lp.z};
  const double h = dot(q, s.a);
  if (h >= g.cutter.fluteLength * (1 - 1e-12)) return;  // the top cap carries no edge
  const Vec3 across = q - h * s.a;
  // Off the teeth's edge span the face carries no edge either: a span's end is an end of
  // the face, found as the others are (halving to kMinInterval), but F runs on across it
  // (scanInterval: a root there is the edge's end crossing the line).
  const bool on = !g.spanned || g.onSpan(h, length(across));
  s.hit[side] = on;
  s.off[side] = !on;
  s.z[side] = lp.z + T.z;
  s.h[side] = h;
  s.theta[side] = std::atan2(dot(across, s.e2), dot(across, s.e1));
  // The rake's lag at the nominal radius (the group's solid is the nominal profile moved
  // out by its radial offset).
  if (g.lag.active()) s.theta[side] -= g.lag(length(across) - g.radial, h);
  if (!on) return;
  if (side == 0) s.normal0 = lp.normal;
}

// A lower bound of the exit height X(t).z from a solid inside the cutter: the straight
// flank's cylinder about the axis `a` through `tip`, of radius R - shrink between the
// heights r + shrink and L - shrink above the tip. The top of the line's chord through
// it is a point of the cutter on the line, so the exit is no lower. In closed form:
// with w = z - tip.z, the squared distance from the axis is A w^2 + B w + C and the
// height along the axis c + w a_z. -inf where the line misses that solid.
// A general cutter's flank need not be straight: its cylinder stands on the upper half
// of the flutes, between the heights L / 2 + shrink and L - shrink, of radius
// min(w(L / 2), w(L)) - shrink. The chain's width w is concave, so it is no less than
// that minimum all over [L / 2, L], and every point within shrink of the cylinder lies
// in the cutter.
double ToothSweep::exitLowerBound(const Group& g, const Vec3& groupTip, const Vec3& a,
                                  double shrink, double x, double y) const {
  const Vec3 tip = g.drop != 0 ? groupTip - g.drop * a : groupTip;
  const double dx = x - tip.x, dy = y - tip.y;
  const double L = g.cutter.fluteLength;
  double R = g.cutter.radius - shrink, base = g.cutter.cornerRadius;
  if (g.cutter.general()) {
    const CutterProfile& p = *g.cutter.profile;
    base = 0.5 * L;
    R = std::min(p.width(base), p.width(L)) - shrink;
  }
  const double c = dx * a.x + dy * a.y;
  const double A = 1 - a.z * a.z, B = -2 * c * a.z, C = dx * dx + dy * dy - c * c - R * R;
  if (!(a.z > 1e-9) || !(R > 0)) return -HUGE_VAL;
  const double sLo = (base + shrink - c) / a.z;
  const double sHi = (L - shrink - c) / a.z;
  double w1 = -HUGE_VAL, w2 = HUGE_VAL;
  if (A > 1e-15) {
    const double disc = B * B - 4 * A * C;
    if (!(disc >= 0)) return -HUGE_VAL;
    const double root = std::sqrt(disc);
    w1 = (-B - root) / (2 * A), w2 = (-B + root) / (2 * A);
  } else if (C > 0) {
    return -HUGE_VAL;  // a vertical axis: the line is outside the cylinder
  }
  const double top = std::min(w2, sHi);
  if (!(top >= std::max(w1, sLo))) return -HUGE_VAL;
  // The quadratic's rounding, relative to the sizes involved.
  return tip.z + top - 1e-9 * (1 + std::abs(top));
}

// A lower bound of every exit height X(t).z over [a.t, b.t]:
//   * any move: every cutter point moves by at most delta = (|tip'| + omega reach) w / 2
//     from its place at the middle pose, so the middle cutter eroded by delta (and by
//     the runout, which the spindle turns) lies inside every cutter of the interval
//     (a point whose delta-ball is in K(tm) is within delta of its own image), and
//     so does the straight part of it;
//   * a constant axis: the straight part pulled in by the runout alone translates
//     linearly, so its exit height is concave in t and the lower of the ends' bounds
//     holds between them (both ends meeting it, so does every t between).
double ToothSweep::exitBound(const Group& g, const Sample& a, const Sample& b, double x,
                             double y) const {
  const double w = b.t - a.t;
  const Sample mid = pose(0.5 * (a.t + b.t));
  const double delta = (tipSpeed_ + curve_.turnRate() * reach_) * 0.5 * w * (1 + 1e-12) + 1e-12;
  double bound = exitLowerBound(g, mid.tip, mid.a, delta + cutter_.teeth.runout, x, y);
  if (translates_) {
    const double ends = std::min(exitLowerBound(g, a.tip, a.a, cutter_.teeth.runout, x, y),
                                 exitLowerBound(g, b.tip, b.a, cutter_.teeth.runout, x, y));
    bound = std::max(bound, ends);
  }
  return bound;
}

// F(b) - F(a) for one side, with theta unwrapped the short way (intervals are small).
double ToothSweep::deltaF(const Sample& a, const Sample& b, int side) const {
  const double dTheta = wrapAngle(b.theta[side] - a.theta[side]);
  return cutter_.teeth.flutes * (dTheta + (b.phi - a.phi) - (b.h[side] - a.h[side]) * helixSlope_) /
         kTwoPi;
}

double ToothSweep::absoluteF(const Sample& s, int side) const {
  return cutter_.teeth.flutes * (s.theta[side] + s.phi - s.h[side] * helixSlope_) / kTwoPi;
}

// Whether F can be trusted to be monotone between a and b on this side: the piercing
// point's own turn (its angle less the edge's lag) is at most half of the spindle's.
bool ToothSweep::calm(const Sample& a, const Sample& b, int side) const {
  const double own =
      wrapAngle(b.theta[side] - a.theta[side]) - (b.h[side] - a.h[side]) * helixSlope_;
  return std::abs(own) <= 0.5 * std::abs(b.phi - a.phi);
}

// A lower bound of h over [a.t, b.t] where a pruning proof exists, else -inf.
double ToothSweep::envelopeBound(const Group& g, Sample& a, Sample& b, double x, double y,
                                 double best) const {
  if (translates_) {
    needEnvelope(g, a, x, y, &b);
    needEnvelope(g, b, x, y, &a);
    if (!a.envHit || !b.envHit || !a.slopeKnown || !b.slopeKnown) return -HUGE_VAL;
    // Two tangent lines of a convex function: their crossing is the lowest either
    // allows (or an end, if they do not cross inside).
    const double sa = a.envSlope, sb = b.envSlope, dt = b.t - a.t;
    // The slack covers the rounding of h and its slope (~1e-12 mm).
    const double slack = 1e-11 * (1 + std::abs(a.envZ) + std::abs(b.envZ));
    if (sb - sa <= 1e-300) return std::min(a.envZ, b.envZ) - slack;
    const double tc = std::clamp((b.envZ - a.envZ - sb * dt) / (sa - sb), 0.0, dt);
    return std::min(std::min(a.envZ, b.envZ), a.envZ + sa * tc) - slack;
  }
  // A turning move: every tooth lies in envelope_ at the spindle's tip (drop_ is 0).
  if (best == HUGE_VAL) return -HUGE_VAL;
  return rayClearsMove(envelope_, curve_, Vec3{x, y, best}, 0.5 * (a.t + b.t), a.t, b.t)
             ? best
             : -HUGE_VAL;
}

// Whether, with a vertical axis, the line stays off the ring of radii where the group's
// span lies over [a.t, b.t]: the line is then parallel to the axis, so every point of
// the solid on it is at its horizontal distance d from the cutter's own axis, and d moves
// by at most v = |tip'| + runout |phi'| per unit t, so it stays within
// (d_a + d_b -+ v w) / 2. Culls a face mill's stretches over its non-cutting bottom.
bool ToothSweep::offSpanRing(const Group& g, const Sample& a, const Sample& b, double x,
                             double y) const {
  const double da = std::hypot(x - a.T.x, y - a.T.y), db = std::hypot(x - b.T.x, y - b.T.y);
  const double vw = (tipSpeed_ + cutter_.teeth.runout * std::abs(phaseRate_)) * (b.t - a.t);
  const double margin = 1e-9 * (1 + cutter_.radius);
  return 0.5 * (da + db + vw) < g.spanRadiusMin - margin ||
         0.5 * (da + db - vw) > g.spanRadiusMax + margin;
}

// Solves F(t) - F(a) = target between a and b (0 < target <= F(b) - F(a), a and b in
// either order of t) for one side, and keeps the crossing if it is the lowest so far.
// Regula falsi with the Illinois rule: F is nearly linear in t (the spindle turns at a
// constant rate), so a few steps bring the height to 1e-13 mm.
void ToothSweep::solveCrossing(const Group& g, const Sample& a, const Sample& b, int side,
                               double target, double x, double y, Crossing& best) const {
  Sample p = a, q = b;  // g(p) < 0 <= g(q), g = F - F(a) - target
  double gp = -target, gq = deltaF(a, b, side) - target;
  double rawP = gp, rawQ = gq;  // g itself (gp, gq carry the Illinois halvings)
  int stale = 0;                // Illinois: halve the end that stayed twice in a row
  const bool longBracket = std::abs(b.t - a.t) > 1.2 * g.quarterPeriod;
  for (int step = 0; step < kSolveSteps && gq != 0; ++step) {
    const double lo = std::min(p.t, q.t), hi = std::max(p.t, q.t);
    double t = p.t + (q.t - p.t) * (gp / (gp - gq));
    // On a bracket longer than a quarter tooth period (a group of few teeth scans in
    // such steps: tooth_groups.cpp) the first iterate lands near the root but on one
    // side, and regula falsi keeps the far end for a few steps. The second iterate goes
    // instead a quarter of the predicted gap past the root that the first one's secant
    // predicts, so that both ends come near it (callgrind, B5o: 3.0 steps a solve
    // instead of 3.7; on B5's quarter-period brackets this costs, so it is not used).
    if (step == 1 && longBracket) {
      const Sample& last = stale == -1 ? p : q;
      const double est = last.t - (stale == -1 ? rawP : rawQ) * (q.t - p.t) / (rawQ - rawP);
      const double probe = est + 0.25 * (est - last.t);
      if (probe > lo && probe < hi) t = probe;
    }
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) break;  // the bracket is down to adjacent doubles
    Sample s = pose(t);
    needSide(g, s, side, x, y, &p, &q);
    if (!s.hit[side]) break;  // the face ends inside: keep the bracket's ends
    const double g = deltaF(a, s, side) - target;
    // Converged when the height's error, |g| times dz/dF across the bracket, is below
    // 1e-13 mm (F is nearly linear in t, so this comes after two or three steps).
    const double dzdg = (q.z[side] - p.z[side]) / (rawQ - rawP);
    if (g == 0 || std::abs(g * dzdg) < 1e-13) {
      keep(s, side, best);
      return;
    }
    if (g < 0) {
      p = s, gp = rawP = g;
      if (stale == -1) gq *= 0.5;
      stale = -1;
    } else {
      q = s, gq = rawQ = g;
      if (stale == 1) gp *= 0.5;
      stale = 1;
    }
  }
  keep(std::abs(rawP) < std::abs(rawQ) ? p : q, side, best);
}

void ToothSweep::keep(const Sample& s, int side, Crossing& best) const {
  if (!s.hit[side] || !(s.z[side] < best.z)) return;
  best.z = s.z[side];
  best.t = s.t;
  best.normal = side == 0 ? s.normal0 : Vec3{0, 0, -1};
}

// The crossings on [a, b]: halves the interval until F is calm on each side that meets
// the cutter at both ends, then solves for every integer F passes.
void ToothSweep::scanInterval(const Group& g, Sample& a, Sample& b, double x, double y, int depth,
                              Crossing& best) const {
  if (envelopeBound(g, a, b, x, y, best.z) >= best.z) return;
  if (g.spanned && vertical_ && offSpanRing(g, a, b, x, y)) return;
  // Where the exit points are proven no lower than the best (exitBound), only the entry
  // points are searched.
  const int sides = exitBound(g, a, b, x, y) >= best.z ? 1 : 2;
  bool split = false;
  for (int side = 0; side < sides; ++side) {
    needSide(g, a, side, x, y);
    needSide(g, b, side, x, y);
    if (a.hit[side] != b.hit[side] || (a.hit[side] && !calm(a, b, side))) split = true;
  }
  // Where the faces agree at both ends but F is not calm, halving stops at a leaf of
  // 1/256 of a tooth period: there the piercing point sweeps round near the axis (every
  // edge meets there, and F's end values show the crossing the sweep makes) or slides
  // fast along a face, and the roots taken are those the end values show.
  bool facesAgree = true;
  for (int side = 0; side < sides; ++side) facesAgree = facesAgree && a.hit[side] == b.hit[side];
  const double limit = facesAgree ? best.leaf : kMinInterval;
  if (split && (depth >= kMaxDepth || b.t - a.t <= limit || best.splitsLeft <= 0)) {
    if (best.splitsLeft <= 0) best.unproven = true;
    split = false;
  }
  if (split) {
    --best.splitsLeft;
    Sample mid = pose(0.5 * (a.t + b.t));
    needEnvelope(g, mid, x, y, &a, &b);
    scanInterval(g, a, mid, x, y, depth + 1, best);
    scanInterval(g, mid, b, x, y, depth + 1, best);
    return;
  }
  for (int side = 0; side < sides; ++side) {
    if (!a.hit[side] || !b.hit[side]) {
      // An end of a face inside an interval of 1e-13: a crossing there is at either end.
      if (a.hit[side] && g.isRoot(absoluteF(a, side))) {
        keep(a, side, best);
      } else if ((a.hit[side] && b.off[side]) || (a.off[side] && b.hit[side])) {
        // A span's end: F is continuous across it, so a root between the ends' values is
        // the span's end on the line (a corner of the edge's swept surface, the lowest
        // point of a round insert's mark): its height is the on-span end's, within the
        // interval's 1e-13.
        const double fa = absoluteF(a, side), fb = fa + deltaF(a, b, side);
        if (g.hasRootIn(std::min(fa, fb), std::max(fa, fb))) keep(a.hit[side] ? a : b, side, best);
      }
      continue;
    }
    // Without runout X(t).z itself is concave in t (the cutter translates linearly).
    if (side == 1 && translates_ && cutter_.teeth.runout <= 0 && std::min(a.z[1], b.z[1]) >= best.z)
      continue;
    const double fa = absoluteF(a, side);
    const double df = deltaF(a, b, side);
    // Every root m of the group with fa < m <= fa + df (or the reverse for a decreasing
    // F): every integer at equal pitch with one group, else each tooth's root modulo
    // flutes.
    const double lo = std::min(fa, fa + df), hi = std::max(fa, fa + df);
    auto solve = [&](double m) {
      if (df > 0)
        solveCrossing(g, a, b, side, m - fa, x, y, best);
      else
        solveCrossing(g, b, a, side, m - lo, x, y, best);
    };
    if (g.everyInteger) {
      for (double m = std::floor(lo) + 1; m <= hi; ++m) solve(m);
    } else {
      const double n = g.flutes;
      for (double r : g.roots)
        for (double m = r + n * (std::floor((lo - r) / n) + 1); m <= hi; m += n)
          if (m > lo) solve(m);
    }
    if (g.isRoot(fa)) keep(a, side, best);
  }
}

LowestPoint ToothSweep::lowestCrossing(double x, double y, const LowestPoint& envelope,
                                       double cutoff) const {
  if (!mirrored_) return clockwiseCrossing(x, y, envelope, cutoff);
  // The mirrored job's search at (x, -y), from the mirrored envelope's lowest point
  // there (its search starts at that point's t*), mirrored back.
  LowestPoint start = envelope;
  if (mirroredEnvelope_ && envelope.hit)
    start = mirroredEnvelope_->lowestPoint(x, -y, nullptr, cutoff);
  LowestPoint out = clockwiseCrossing(x, -y, start, cutoff);
  out.normal.y = -out.normal.y;
  return out;
}

LowestPoint ToothSweep::clockwiseCrossing(double x, double y, const LowestPoint& envelope,
                                          double cutoff) const {
  LowestPoint miss;
  if (!envelope.hit || !(envelope.z < cutoff) || !(phaseRate_ > 0)) return miss;
  Crossing best{cutoff, 0, Vec3{0, 0, -1}, kMaxSplits, false, 0};
  bool scanWhole = !translates_;
  double tStar = 0;
  if (translates_) {
    // t* of the envelope's lowest point: the swept solid's support point in direction n
    // is the cutter's support point plus a point of the tip's segment (lowered by drop_).
    const Vec3 p0 = curve_.tipStart(), d = curve_.tipEnd() - p0;
    const double dd = dot(d, d);
    if (dd > 0) {
      Vec3 onPath =
          Vec3{x, y, envelope.z} - cutterSupport(envelope_, curve_.axis(0), envelope.normal);
      if (drop_ != 0) onPath = onPath + drop_ * curve_.axis(0);
      tStar = std::clamp(dot(onPath - p0, d) / dd, 0.0, 1.0);
    }
  }
  bool unproven = false;
  for (const Group& g : groups_) {
    best.splitsLeft = kMaxSplits;
    best.unproven = false;
    best.leaf = g.leaf;
    scanGroup(g, x, y, tStar, scanWhole, best);
    unproven = unproven || best.unproven;
  }
  if (unproven) unprovenCrossingCount.fetch_add(1, std::memory_order_relaxed);
  if (!(best.z < cutoff)) return miss;
  LowestPoint out;
  out.hit = true;
  out.z = best.z;
  out.normal = best.normal;
  out.t = best.t;
  return out;
}

// One group's crossings, lowering `best`.
void ToothSweep::scanGroup(const Group& g, double x, double y, double tStar, bool scanWhole,
                           Crossing& best) const {
  const double step = g.step;
  if (!scanWhole) {
    // Outward in both directions from t*, nearest intervals first, until h has risen to
    // the best crossing and still rises outward (a subgradient of that sign): h is
    // convex, so beyond such a sample it stays higher. (t* is the envelope's minimum to
    // round-off, and another group's h has its own: the slope test keeps the stop proven
    // wherever the scan starts.) The line meets the envelope on an interval of t;
    // leaving it ends the scan.
    Sample left = pose(tStar);
    needEnvelope(g, left, x, y);
    Sample right = left;
    bool goLeft = tStar > 0, goRight = tStar < 1;
    if (!left.envHit) goLeft = goRight = false, scanWhole = true;
    auto risen = [&](const Sample& s, double sign) {
      return !s.envHit || (s.envZ >= best.z && s.slopeKnown && sign * s.envSlope >= 0);
    };
    while (goLeft || goRight) {
      if (goRight) {
        Sample next = pose(std::min(1.0, right.t + step));
        needEnvelope(g, next, x, y, &right);
        scanInterval(g, right, next, x, y, 0, best);
        goRight = next.t < 1 && !risen(next, 1);
        right = next;
      }
      if (goLeft) {
        Sample next = pose(std::max(0.0, left.t - step));
        needEnvelope(g, next, x, y, &left);
        scanInterval(g, next, left, x, y, 0, best);
        goLeft = next.t > 0 && !risen(next, -1);
        left = next;
      }
    }
  }
  if (scanWhole) {
    const int n = std::max(2, int(std::ceil(1 / step)));
    Sample prev = pose(0);
    for (int i = 1; i <= n; ++i) {
      Sample next = pose(double(i) / n);
      scanInterval(g, prev, next, x, y, 0, best);
      prev = next;
    }
  }
}

}  // namespace scallop
