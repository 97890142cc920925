// The hunt's certificates (hunt_reference.h has the derivation).
#include "hunt/hunt_reference.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include "base/constants.h"
#include "sweep/machine_reference.h"

namespace scallop::hunt {

namespace {

// The parts of a tool-frame point p that the measure and its gradient need.
struct CorePart {
  double s, rho;   // along the axis; distance from it
  Vec3 e;          // unit radial direction (zero on the axis)
  double ds, dr;   // p minus its nearest point of the core K0, along a and along e
  double dist;     // the distance, hypot(ds, dr)
  // The unit direction from the nearest core point to p, made of the exact unit vectors
  // a and e (not the difference of two points): on a face one of ds, dr is exactly zero,
  // so the normal is exact however near p lies.
  Vec3 direction(const Vec3& a) const { return (a * ds + e * dr) / dist; }
};

CorePart corePart(const HuntCutter& c, const Vec3& a, const Vec3& p) {
  CorePart k;
  k.s = dot(p, a);
  const Vec3 perp = p - a * k.s;
  k.rho = length(perp);
  k.e = k.rho > 0 ? perp / k.rho : Vec3{};
  k.ds = k.s - std::clamp(k.s, c.r, c.L);
  k.dr = k.rho - std::min(k.rho, c.Rb());
  k.dist = std::hypot(k.ds, k.dr);
  return k;
}

// Golden-section minimum of a convex f on [0, 1]: the argument.
template <class F>
double goldenMin(F&& f) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double lo = 0, hi = 1, x1 = hi - g, x2 = lo + g, f1 = f(x1), f2 = f(x2);
  double best = f(0) <= f(1) ? 0.0 : 1.0, fb = std::min(f(0), f(1));
  for (int i = 0; i < 120 && hi - lo > 1e-15; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  if (f1 < fb) best = x1, fb = f1;
  if (f2 < fb) best = x2;
  return best;
}

// A separating plane between the ray below p and the convex solid (cutter g with axis a)
// (+) [c0, c1] (tips): true when one is found and checked with the support function.
bool planeSeparates(const HuntCutter& g, const Vec3& a, const Vec3& c0, const Vec3& c1,
                    const Vec3& p, bool* inside) {
  const Vec3 d = c1 - c0;
  auto measure = [&](double lam) { return insideMeasure(g, a, p - (c0 + d * lam)); };
  const double lam = goldenMin(measure);
  const Vec3 k = p - (c0 + d * lam);
  *inside = measure(lam) <= 0;
  if (*inside) return false;
  const CorePart part = corePart(g, a, k);
  const bool capBranch = part.s - g.L > part.dist - g.r;
  const Vec3 grad = capBranch || !(part.dist > 0) ? a : part.direction(a);
  const double pad = 1e-12 * (1 + length(p) + g.reach());
  auto separates = [&](const Vec3& n) {
    const double h = supportValue(g, a, n) + std::max(dot(n, c0), dot(n, c1));
    return dot(n, p) > h + pad;
  };
  // A downward normal covers the whole ray below p; a horizontal one the whole line.
  if (grad.z <= 0 && separates(grad)) return true;
  const double hl = std::hypot(grad.x, grad.y);
  if (hl > 0 && separates(Vec3{grad.x / hl, grad.y / hl, 0})) return true;
  // A line beside the solid, seen from above it (the nearest point on the top face): the
  // best horizontal normal, scanned at 64 angles and refined about the best.
  auto margin = [&](double phi) {
    const Vec3 n{std::cos(phi), std::sin(phi), 0};
    return dot(n, p) - supportValue(g, a, n) - std::max(dot(n, c0), dot(n, c1));
  };
  constexpr int kAngles = 64;
  const double step = 2 * kPi / kAngles;
  int best = 0;
  for (int k = 1; k < kAngles; ++k)
    if (margin(k * step) > margin(best * step)) best = k;
  const double phi = (best - 1) * step + 2 * step * goldenMin([&](double u) {
    return -margin((best - 1) * step + 2 * step * u);
  });
  return separates(Vec3{std::cos(phi), std::sin(phi), 0});
}

}  // namespace

double insideMeasure(const HuntCutter& c, const Vec3& a, const Vec3& p) {
  const CorePart k = corePart(c, a, p);
  return std::max(k.dist - c.r, k.s - c.L);
}

double supportValue(const HuntCutter& c, const Vec3& a, const Vec3& n) {
  const double na = dot(n, a);
  const double np = length(n - a * na);
  const double torus = c.r * na + c.Rb() * np + c.r * (na <= 0 ? length(n) : np);
  return std::max(torus, c.L * na + c.R * np);
}

bool stationaryLowest(const HuntCutter& c, const Vec3& tip, const Vec3& a, double x, double y,
                      double* z) {
  // The line meets the cutter only inside its bounding sphere (centre L/2 up the axis).
  const Vec3 centre = tip + a * (c.L / 2);
  const double rs = std::sqrt(c.L * c.L / 4 + c.R * c.R);
  const double dh = std::hypot(x - centre.x, y - centre.y);
  if (dh > rs) return false;
  const double w = std::sqrt(rs * rs - dh * dh);
  const double pad = 1e-9 * (1 + rs);
  double zz = centre.z - w - pad;
  const double zTop = centre.z + w + pad;
  // Newton from below on the convex measure along the line: every step is at or below
  // the lowest root (any subgradient's tangent stays below a convex function).
  for (int iter = 0; iter < 400; ++iter) {
    const Vec3 p = Vec3{x, y, zz} - tip;
    const CorePart k = corePart(c, a, p);
    const double core = k.dist - c.r, cap = k.s - c.L;
    const double f = std::max(core, cap);
    if (f <= 0) {
      *z = zz;
      return true;
    }
    double slope;
    if (cap >= core) {
      slope = a.z;
    } else {
      // d/dz of the distance to the core: the direction's z.
      slope = k.dist > 0 ? k.direction(a).z : 0.0;
    }
    if (!(slope < 0)) return false;
    const double step = -f / slope;
    zz += step;
    if (zz > zTop) return false;
    if (step < 1e-14 * (1 + std::fabs(zz))) {
      // A grazing line: Newton crawls. Accept a root within round-off, else a miss.
      if (f <= 1e-12 * (1 + c.R)) {
        *z = zz;
        return true;
      }
      return false;
    }
  }
  *z = zz;
  return true;
}

Verdict provesReached(const HuntCutter& c, const HuntCurve& curve, const Vec3& p) {
  // Best first by the least measure an interval could reach: its middle's measure less
  // the most the point moves in the body frame over the interval.
  struct Interval {
    double t0, t1, key;
    bool operator<(const Interval& o) const { return key > o.key; }
  };
  auto keyOf = [&](double t0, double t1, bool* inside) {
    const double tm = 0.5 * (t0 + t1), h = 0.5 * (t1 - t0);
    const Vec3 tip = curve.tip(tm);
    const double f = insideMeasure(c, curve.axis(tm), p - tip);
    *inside = f <= 0;
    const double move = curve.speed * h + curve.turn * h * (length(p - tip) + curve.speed * h);
    return f - move * (1 + 1e-12) - 1e-13 * (1 + length(p));
  };
  std::priority_queue<Interval> queue;
  for (int k = 0; k < 16; ++k) {
    bool inside = false;
    const double t0 = k / 16.0, t1 = (k + 1) / 16.0;
    const double key = keyOf(t0, t1, &inside);
    if (inside) return Verdict::kProven;
    queue.push({t0, t1, key});
  }
  for (int visited = 0; visited < 20000; ++visited) {
    if (queue.empty() || queue.top().key > 0) return Verdict::kFails;
    const Interval iv = queue.top();
    queue.pop();
    const double tm = 0.5 * (iv.t0 + iv.t1);
    if (!(tm > iv.t0 && tm < iv.t1)) continue;  // cannot be split: its middle was tested
    for (const auto& [a, b] : {std::pair{iv.t0, tm}, std::pair{tm, iv.t1}}) {
      bool inside = false;
      const double key = keyOf(a, b, &inside);
      if (inside) return Verdict::kProven;
      queue.push({a, b, key});
    }
  }
  return Verdict::kUnresolved;
}

Verdict provesClear(const HuntCutter& c, const HuntCurve& curve, const Vec3& p, double* lower) {
  const bool convex = curve.turn == 0 && curve.accel == 0;
  std::vector<std::pair<double, double>> stack{{0.0, 1.0}};
  for (int visited = 0; visited < 20000; ++visited) {
    if (stack.empty()) return Verdict::kProven;
    const auto [t0, t1] = stack.back();
    stack.pop_back();
    const double tm = 0.5 * (t0 + t1), h = 0.5 * (t1 - t0);
    const Vec3 a = curve.axis(tm);
    // The cutters over [t0, t1] lie in K(tm) grown by eps, swept along the chord.
    const double eps = curve.turn * h * c.reach() * (1 + 1e-12) + curve.accel * h * h / 2;
    const HuntCutter g = c.grown(eps);
    const Vec3 c0 = curve.tip(t0) - a * eps, c1 = curve.tip(t1) - a * eps;
    bool inside = false;
    if (planeSeparates(g, a, c0, c1, p, &inside)) continue;
    // Not separated: a real cutter position below p proves the height too high.
    double zz = 0;
    if (stationaryLowest(c, curve.tip(tm), a, p.x, p.y, &zz) && zz < p.z &&
        insideMeasure(c, a, Vec3{p.x, p.y, zz + 1e-9} - curve.tip(tm)) <= 0) {
      if (lower) *lower = zz;
      return Verdict::kFails;
    }
    if (convex && inside && eps == 0) {
      // The exact convex sweep holds p itself: some position reaches it; find it.
      for (int k = 0; k <= 64; ++k) {
        const double t = t0 + (t1 - t0) * k / 64;
        if (stationaryLowest(c, curve.tip(t), a, p.x, p.y, &zz) && zz < p.z) {
          if (lower) *lower = zz;
          return Verdict::kFails;
        }
      }
    }
    if (!(tm > t0 && tm < t1)) return Verdict::kUnresolved;
    stack.push_back({t0, tm});
    stack.push_back({tm, t1});
  }
  return Verdict::kUnresolved;
}

HuntCurve straightCurve(const Vec3& p0, const Vec3& p1, const Vec3& a0, const Vec3& a1) {
  const Vec3 u0 = normalize(a0), u1 = normalize(a1);
  const double phi = std::acos(std::clamp(dot(u0, u1), -1.0, 1.0));
  HuntCurve curve;
  curve.tip = [=](double t) { return p0 + (p1 - p0) * t; };
  if (phi < 1e-12) {
    curve.axis = [=](double) { return u0; };
  } else {
    // Slerp as CONVENTIONS.md "Tool pose" writes it.
    curve.axis = [=](double t) {
      return (u0 * std::sin((1 - t) * phi) + u1 * std::sin(t * phi)) / std::sin(phi);
    };
    curve.turn = phi;
  }
  curve.speed = length(p1 - p0);
  return curve;
}

HuntCurve rotaryCurve(bool tableAC, const Vec3& p0, const Vec3& p1, double tilt0, double tilt1,
                      double spin0, double spin1) {
  const RotaryKinematics k = tableAC ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
  HuntCurve curve;
  curve.tip = [=](double t) { return p0 + (p1 - p0) * t; };
  curve.axis = [=](double t) {
    return conventionAxis(k, tilt0 + (tilt1 - tilt0) * t, spin0 + (spin1 - spin0) * t);
  };
  curve.speed = length(p1 - p0);
  curve.turn = std::fabs(tilt1 - tilt0) + std::fabs(spin1 - spin0);
  return curve;
}

HuntCurve jointCurve(bool tableAC, const Vec3& j0, const Vec3& j1, double tilt0, double tilt1,
                     double spin0, double spin1) {
  TableMachine machine;
  machine.kinematics = tableAC ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
  HuntCurve curve;
  curve.tip = [=](double t) {
    return trtForward(machine, j0 + (j1 - j0) * t, tilt0 + (tilt1 - tilt0) * t,
                      spin0 + (spin1 - spin0) * t);
  };
  curve.axis = [=](double t) {
    return conventionAxis(machine.kinematics, tilt0 + (tilt1 - tilt0) * t,
                          spin0 + (spin1 - spin0) * t);
  };
  // tip = M(t) q(t) with |M^(n) v| <= w^n |v| and q linear (pose_curve.h's bounds, derived
  // again here): |tip'| <= |q'| + w Q, |tip''| <= w^2 Q + 2 w |q'|, Q = max |q|.
  const double w = std::fabs(tilt1 - tilt0) + std::fabs(spin1 - spin0);
  const double q = std::max(length(j0), length(j1)), dq = length(j1 - j0);
  curve.turn = w;
  curve.speed = (dq + w * q) * (1 + 1e-12);
  curve.accel = (w * w * q + 2 * w * dq) * (1 + 1e-12);
  return curve;
}

HuntCurve arcCurve(const Vec3& centre, double rho, double th0, double sweep, double rise,
                   const Vec3& axis) {
  const Vec3 a = normalize(axis);
  HuntCurve curve;
  curve.tip = [=](double t) {
    const double th = th0 + sweep * t;
    return centre + Vec3{rho * std::cos(th), rho * std::sin(th), rise * t};
  };
  curve.axis = [=](double) { return a; };
  curve.speed = std::hypot(rho * sweep, rise) * (1 + 1e-12);
  curve.accel = rho * sweep * sweep * (1 + 1e-12);
  return curve;
}

}  // namespace scallop::hunt
