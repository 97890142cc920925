// The brute-force reference of the teeth model (tooth_reference.h) and the tests that
// check the reference itself: a second, plain method (a uniform grid), and closed forms
// derived by hand (the flat bottom of a vertical end mill, the meridian arcs of a ball
// with lead). Named *_test.cpp so that tests/CMakeLists.txt's glob compiles it.
//
// Nothing here calls sweep/*.cpp: the reference must stay independent of the code it
// judges (tests/sweep/tooth_sweep_test.cpp compares the two).
#include "sweep/tooth_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>
#include <random>
#include <vector>

#include "base/constants.h"

namespace scallop {
namespace ref {

namespace {

// Newton's answer is a crossing when the edge point is this close to the line, mm.
constexpr double kRootTolerance = 1e-12;
// Cells smaller than this (B, mm) with no root are near-crossings.
constexpr double kLeafBound = 1e-10;
// The search stops when no cell can hold a crossing this much below the best, mm.
constexpr double kSlack = 1e-9;
// Newton is tried from cells whose bound B is below this, mm.
constexpr double kNewtonBound = 1e-2;

// A general cutter's chain (cutter_profile.h) by arc length: each piece's length and,
// for an arc, its centre found here from its ends and radius (on the solid's side, the
// left of the chain's direction from the tip up) and its start angle about it.
struct ChainPiece {
  double r0, s0, r1, s1, radius, length;
  double cr = 0, cs = 0, angle0 = 0;
};

std::vector<ChainPiece> chainPieces(const Cutter& c) {
  std::vector<ChainPiece> out;
  for (const ProfileSegment& g : c.profile->segments()) {
    ChainPiece p{g.rho0, g.s0, g.rho1, g.s1, g.arcRadius, 0};
    const double dr = g.rho1 - g.rho0, ds = g.s1 - g.s0, chord = std::hypot(dr, ds);
    if (!(chord > 0)) continue;
    if (g.arcRadius > 0) {
      const double half = 0.5 * chord;
      const double off = std::sqrt(std::max(0.0, g.arcRadius * g.arcRadius - half * half));
      p.cr = 0.5 * (g.rho0 + g.rho1) - ds / chord * off;
      p.cs = 0.5 * (g.s0 + g.s1) + dr / chord * off;
      p.angle0 = std::atan2(g.s0 - p.cs, g.rho0 - p.cr);
      double span = std::atan2(g.s1 - p.cs, g.rho1 - p.cr) - p.angle0;
      while (span <= 0) span += 2 * kPi;  // anticlockwise about the centre
      p.length = g.arcRadius * span;
    } else {
      p.length = chord;
    }
    out.push_back(p);
  }
  return out;
}

// The piece's point at arc length v from its start (v may run past either end: a
// line goes straight on, an arc round its circle).
EdgeSpot onPiece(const ChainPiece& p, double v) {
  if (p.radius > 0) {
    const double a = p.angle0 + v / p.radius;
    return {p.cr + p.radius * std::cos(a), p.cs + p.radius * std::sin(a)};
  }
  const double f = v / p.length;
  return {p.r0 + (p.r1 - p.r0) * f, p.s0 + (p.s1 - p.s0) * f};
}

// The tangent line of a piece at its start (v < 0) or end (v > its length), straight on.
EdgeSpot straightOn(const ChainPiece& p, double v) {
  const double eps = 1e-6 * std::min(1.0, p.length);
  const bool atStart = v < 0;
  const EdgeSpot a = onPiece(p, atStart ? 0 : p.length);
  const EdgeSpot b = onPiece(p, atStart ? eps : p.length - eps);
  const double d = atStart ? -v : v - p.length;
  return {a.rho + (a.rho - b.rho) / eps * d, a.h + (a.h - b.h) / eps * d};
}

EdgeSpot chainAt(const std::vector<ChainPiece>& pieces, double u) {
  if (u < 0) return straightOn(pieces.front(), u);
  for (const ChainPiece& p : pieces) {
    if (u <= p.length) return onPiece(p, u);
    u -= p.length;
  }
  return straightOn(pieces.back(), pieces.back().length + u);
}

// The meridian profile by arc length, extended beyond [0, U] (straight on) so that
// Newton's differences work at the ends; the roots kept are inside.
EdgeSpot profileAt(const Cutter& c, double u) {
  if (c.general()) return chainAt(chainPieces(c), u);
  const double R = c.radius, r = c.cornerRadius, rb = c.bottomRadius();
  const double cornerEnd = rb + r * kPi / 2;
  if (u <= rb && (rb > 0 || u < 0)) return {u, 0};
  if (u < cornerEnd) {
    const double alpha = (u - rb) / r;
    return {rb + r * std::sin(alpha), r * (1 - std::cos(alpha))};
  }
  return {R, r + (u - cornerEnd)};
}

// A tooth's rake face (tooth_geometry.h's ToothRake): in the tooth's frame (radial c,
// trailing s, axial h) the plane s = (c - rho0) tan(gr) + (h - h0) tan(ga) through the
// profile's point (rho0, h0) at the start of the tooth's span. The edge point of the
// profile's circle at (rho, h) is where the circle meets it: the angle lambda from the
// radial line that solves
//     g(lambda) = rho sin(lambda) - (rho cos(lambda) - rho0) tan(gr) - (h - h0) tan(ga) = 0,
// found here by bisection on (gr - pi / 2, gr + pi / 2), where g' = rho cos(lambda - gr)
// / cos(gr) > 0 (the root through P0: lambda = 0 there).
struct Rake {
  bool on = false;
  double gr = 0, ga = 0, rho0 = 0, h0 = 0;
  Rake(const ToothRake& r, const EdgeSpot& p0)
      : on(r.axialDeg != 0 || r.radialDeg != 0),
        gr(degToRad(r.radialDeg)),
        ga(degToRad(r.axialDeg)),
        rho0(p0.rho),
        h0(p0.h) {}
  double lag(const EdgeSpot& p) const {
    if (!on) return 0;
    if (p.rho <= 0) return gr;  // the axis: the plane through it is the radial line turned by gr
    auto g = [&](double l) {
      return p.rho * std::sin(l) - (p.rho * std::cos(l) - rho0) * std::tan(gr) -
             (p.h - h0) * std::tan(ga);
    };
    double lo = gr - kPi / 2, hi = gr + kPi / 2;
    for (int i = 0; i < 64 && hi - lo > 1e-16; ++i) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  // A bound of (rho + |dr|) |d lambda / du| along the profile (by arc length, |rho'|,
  // |h'| <= 1): differentiating g = 0,
  //     d lambda / du = (tan(ga) cos(gr) h' - sin(lambda - gr) rho') / (rho cos(lambda - gr)),
  // and the input check keeps |sin(lambda - gr)| <= sin(60 deg) (Cutter::checkRakes), so
  // cos(lambda - gr) >= 1/2 and (rho + |dr|) |lambda'| <= 2 (1 + |dr| / rho) (|tan(ga)
  // cos(gr)| + sin(60 deg)), rho no less than the span's least radius rhoMin.
  double turnBound(double dr, double rhoMin) const {
    if (!on) return 0;
    const double grow = dr == 0 ? 1 : 1 + dr / rhoMin;  // rhoMin > 0 where a tooth is offset
    return 2 * grow * (std::fabs(std::tan(ga) * std::cos(gr)) + std::sin(kPi / 3));
  }
};

// The cutter, the move and the fixed parts of the definition.
struct Edges {
  Cutter c;
  ToothMove m;
  Vec3 e1, e2, a0;   // the spindle frame at t = 0
  Vec3 w;            // the turn's axis
  double turn = 0;   // the turn's angle, rad
  double slope = 0;  // tan(beta) / R
  double psiR = 0;   // runout phase, rad
  double U = 0;      // edge length
  double tipSpeed = 0;
  std::vector<double> psi;        // each tooth's body angle, rad
  std::vector<double> dr, da;     // each tooth's offsets, mm
  std::vector<double> uLo, uHi;   // each tooth's edge: arc lengths [uLo, uHi] (its span)
  std::vector<Rake> rake;         // each tooth's rake face
  std::vector<double> Lu;         // each tooth's |dP/du| bound
  double drMost = 0, daMost = 0;  // their largest sizes

  Edges(const Cutter& cutter, const ToothMove& move) : c(cutter), m(move) {
    if (c.general()) chain = chainPieces(c);
    a0 = normalize(m.a0);
    const Vec3 a1 = normalize(m.a1);
    const Vec3 ref = std::fabs(a0.x) > std::cos(kPi / 6) ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    e1 = normalize(ref - a0 * dot(ref, a0));
    e2 = m.counterClockwise ? cross(e1, a0) : cross(a0, e1);
    const int flutes = c.teeth.flutes;
    for (int k = 0; k < flutes; ++k) {
      const bool pitch = !c.teeth.toothAnglesDeg().empty(),
                 offsets = !c.teeth.toothOffsets().empty();
      psi.push_back(pitch ? degToRad(c.teeth.toothAnglesDeg()[size_t(k)]) : 2 * kPi * k / flutes);
      dr.push_back(offsets ? c.teeth.toothOffsets()[size_t(k)].radial : 0);
      da.push_back(offsets ? c.teeth.toothOffsets()[size_t(k)].axial : 0);
      drMost = std::max(drMost, std::fabs(dr.back()));
      daMost = std::max(daMost, std::fabs(da.back()));
    }
    const Vec3 n = cross(a0, a1);
    const double s = length(n);
    turn = std::atan2(s, dot(a0, a1));
    if (turn > 1e-12) {
      w = n / s;
    } else {
      turn = 0;
    }
    const double beta = degToRad(c.teeth.helixDeg);
    slope = std::tan(beta) / c.radius;
    psiR = degToRad(c.teeth.runoutPhaseDeg);
    U = edgeLength(c);
    for (int k = 0; k < flutes; ++k) {
      const bool spans = !c.teeth.edgeSpans().empty();
      uLo.push_back(spans ? c.teeth.edgeSpans()[size_t(k)].from : 0);
      uHi.push_back(spans ? c.teeth.edgeSpans()[size_t(k)].to : U);
      // Moved in (dr < 0), the edge ends at the axis: its flat bottom's points u < -dr
      // (radius u + dr < 0) would pass to the other side and are not edge (moved out, it
      // starts at radius dr: point() needs nothing more).
      uLo.back() = std::max(uLo.back(), -dr[size_t(k)]);
    }
    // |dP/du|: the meridian by arc length, and the turn of a point at radius at most
    // R + |dr|max: the helix's, and the rake's (Rake::turnBound).
    for (int k = 0; k < flutes; ++k) {
      const ToothRake tr =
          c.teeth.toothRakes().empty() ? ToothRake{} : c.teeth.toothRakes()[size_t(k)];
      const double from = c.teeth.edgeSpans().empty() ? 0 : c.teeth.edgeSpans()[size_t(k)].from;
      rake.push_back(Rake(tr, spot(from)));
      const double rhoMin = spot(uLo[size_t(k)]).rho;
      Lu.push_back(std::hypot(1.0, (c.radius + drMost) * slope +
                                       rake.back().turnBound(std::fabs(dr[size_t(k)]), rhoMin)));
    }
    tipSpeed = length(m.p1 - m.p0);
  }

  // Rodrigues: the rotation about w by turn t.
  Vec3 rotate(const Vec3& v, double t) const {
    if (turn == 0) return v;
    const double ang = turn * t, co = std::cos(ang), si = std::sin(ang);
    return v * co + cross(w, v) * si + w * (dot(w, v) * (1 - co));
  }

  std::vector<ChainPiece> chain;  // a general cutter's

  EdgeSpot spot(double u) const { return c.general() ? chainAt(chain, u) : profileAt(c, u); }

  Vec3 point(int k, double u, double t) const {
    const EdgeSpot s = spot(u);
    const double phi = m.phaseStart + m.phaseRate * t;
    const double ang = psi[size_t(k)] + s.h * slope + rake[size_t(k)].lag(s) - phi;
    const Vec3 body = (e1 * std::cos(psiR - phi) + e2 * std::sin(psiR - phi)) * c.teeth.runout +
                      (e1 * std::cos(ang) + e2 * std::sin(ang)) * (s.rho + dr[size_t(k)]) +
                      a0 * (s.h - da[size_t(k)]);
    return m.p0 + (m.p1 - m.p0) * t + rotate(body, t);
  }

  // |dP/dt| over a cell whose top (largest u) is uTop.
  double Lt(double uTop) const {
    // A general chain's distance from the tip need not grow along it: its bound, R and L.
    const EdgeSpot s = c.general() ? EdgeSpot{c.radius, c.fluteLength} : spot(std::min(uTop, U));
    return tipSpeed + (turn + std::fabs(m.phaseRate)) *
                          (c.teeth.runout + std::hypot(s.rho + drMost, s.h + daMost));
  }

  // The t interval where the tip is within reach of the line: outside it no edge point
  // (all within runout + hypot(R, L) of the tip) can be on the line.
  bool window(double x, double y, double& t0, double& t1) const {
    const double reach =
        c.teeth.runout + std::hypot(c.radius + drMost, c.fluteLength + daMost) + 1e-9;
    const double dx = m.p0.x - x, dy = m.p0.y - y;
    const double vx = m.p1.x - m.p0.x, vy = m.p1.y - m.p0.y;
    const double a = vx * vx + vy * vy, b = 2 * (dx * vx + dy * vy),
                 cc = dx * dx + dy * dy - reach * reach;
    if (a == 0) {
      if (cc > 0) return false;
      t0 = 0, t1 = 1;
      return true;
    }
    const double disc = b * b - 4 * a * cc;
    if (disc < 0) return false;
    const double sq = std::sqrt(disc);
    t0 = std::max(0.0, (-b - sq) / (2 * a));
    t1 = std::min(1.0, (-b + sq) / (2 * a));
    return t0 <= t1;
  }

  // Newton (with a backtracking line search, Levenberg-damped) on P(u, t).xy = (x, y)
  // from (u, t), clamped to tooth k's [uLo, uHi] x [0, 1]. t is scaled by `ts` (mm per unit t) so
  // both unknowns are lengths.
  bool newton(int k, double x, double y, double ts, double& u, double& t, Vec3& p) const {
    auto resid = [&](double uu, double tt, Vec3& q) {
      q = point(k, uu, tt);
      return std::hypot(q.x - x, q.y - y);
    };
    double res = resid(u, t, p);
    for (int it = 0; it < 60; ++it) {
      if (res <= kRootTolerance) return true;
      // Central differences in u and in s = ts t (both mm).
      const double h = 1e-7;
      const Vec3 pu = (point(k, u + h, t) - point(k, u - h, t)) / (2 * h);
      const Vec3 pt = (point(k, u, t + h / ts) - point(k, u, t - h / ts)) / (2 * h);
      const double fx = p.x - x, fy = p.y - y;
      // J = [pu.x pt.x; pu.y pt.y]; (J^T J + mu I) d = -J^T f.
      const double a11 = pu.x * pu.x + pu.y * pu.y, a22 = pt.x * pt.x + pt.y * pt.y,
                   a12 = pu.x * pt.x + pu.y * pt.y;
      const double mu = 1e-14 * (a11 + a22) + 1e-300;
      const double g1 = -(pu.x * fx + pu.y * fy), g2 = -(pt.x * fx + pt.y * fy);
      const double det = (a11 + mu) * (a22 + mu) - a12 * a12;
      if (!(det > 0)) return false;
      const double du = ((a22 + mu) * g1 - a12 * g2) / det;
      const double ds = ((a11 + mu) * g2 - a12 * g1) / det;
      bool improved = false;
      for (double lambda = 1; lambda > 1e-9; lambda *= 0.5) {
        const double un = std::clamp(u + lambda * du, uLo[size_t(k)], uHi[size_t(k)]);
        const double tn = std::clamp(t + lambda * ds / ts, 0.0, 1.0);
        Vec3 q;
        const double rn = resid(un, tn, q);
        if (rn < res) {
          u = un, t = tn, p = q, res = rn;
          improved = true;
          break;
        }
      }
      if (!improved) return res <= kRootTolerance;
    }
    return res <= kRootTolerance;
  }
};

struct Cell {
  int k;
  double u0, u1, t0, t1;
  Vec3 p;  // P at the centre
  double B, zLow;
  bool tried;
};

struct ByLowBound {
  bool operator()(const Cell& a, const Cell& b) const { return a.zLow > b.zLow; }
};

}  // namespace

double edgeLength(const Cutter& c) {
  if (c.general()) {
    double u = 0;
    for (const ChainPiece& p : chainPieces(c)) u += p.length;
    return u;
  }
  return c.bottomRadius() + c.cornerRadius * kPi / 2 + (c.fluteLength - c.cornerRadius);
}

EdgeSpot edgeSpot(const Cutter& c, double u) {
  return profileAt(c, std::clamp(u, 0.0, edgeLength(c)));
}

Vec3 toothEdgePoint(const Cutter& c, const ToothMove& m, int k, double u, double t) {
  return Edges(c, m).point(k, u, t);
}

ToothHit toothLowest(const Cutter& c, const ToothMove& m, double x, double y, ToothStats* stats) {
  const Edges e(c, m);
  ToothStats local;
  ToothStats& st = stats ? *stats : local;
  ToothHit best;
  double bestZ = HUGE_VAL;
  double tw0, tw1;
  if (!e.window(x, y, tw0, tw1)) return best;
  const double ts = e.Lt(e.U);

  std::priority_queue<Cell, std::vector<Cell>, ByLowBound> heap;
  auto push = [&](int k, double u0, double u1, double t0, double t1, bool tried) {
    Cell cell{k, u0, u1, t0, t1, {}, 0, 0, tried};
    cell.p = e.point(k, 0.5 * (u0 + u1), 0.5 * (t0 + t1));
    ++st.cells;
    cell.B = e.Lu[size_t(k)] * 0.5 * (u1 - u0) + e.Lt(u1) * 0.5 * (t1 - t0);
    if (std::hypot(cell.p.x - x, cell.p.y - y) > cell.B) return;
    cell.zLow = cell.p.z - cell.B;
    if (cell.zLow < bestZ) heap.push(cell);
  };
  auto keep = [&](int k, double u, double t, const Vec3& p) {
    if (p.z < bestZ) {
      bestZ = p.z;
      best = {true, p.z, t, u, k};
    }
  };

  // Top cells: the spindle turns by at most pi / 8, the tip moves at most R / 4, the
  // axis turns by at most 0.05 rad; u pieces of at most R / 4 between the profile's
  // junctions.
  const double span = tw1 - tw0;
  const int nt =
      std::max(1, int(std::ceil(span * std::max({std::fabs(m.phaseRate) / (kPi / 8),
                                                 e.tipSpeed / (0.25 * c.radius), e.turn / 0.05}))));
  const double rb = c.bottomRadius(), r = c.cornerRadius;
  // The profile's junctions by arc length: the bull's (or ball's, flat's), or a chain's.
  std::vector<double> junctions{rb, rb + r * kPi / 2};
  if (c.general()) {
    junctions.clear();
    double u = 0;
    for (const ChainPiece& p : chainPieces(c)) junctions.push_back(u += p.length);
  }
  for (int k = 0; k < c.teeth.flutes; ++k) {
    // The tooth's span, cut at the profile's junctions inside it.
    const double lo = e.uLo[size_t(k)], hi = e.uHi[size_t(k)];
    std::vector<double> uCuts{lo};
    for (double j : junctions)
      if (j > uCuts.back() && j < hi) uCuts.push_back(j);
    if (hi > uCuts.back()) uCuts.push_back(hi);
    for (size_t s = 1; s < uCuts.size(); ++s) {
      const int nu = std::max(1, int(std::ceil((uCuts[s] - uCuts[s - 1]) / (0.25 * c.radius))));
      for (int i = 0; i < nu; ++i) {
        const double u0 = uCuts[s - 1] + (uCuts[s] - uCuts[s - 1]) * i / nu;
        const double u1 =
            i + 1 == nu ? uCuts[s] : uCuts[s - 1] + (uCuts[s] - uCuts[s - 1]) * (i + 1) / nu;
        for (int j = 0; j < nt; ++j)
          push(k, u0, u1, tw0 + span * j / nt, j + 1 == nt ? tw1 : tw0 + span * (j + 1) / nt,
               false);
      }
    }
  }

  while (!heap.empty()) {
    const Cell cell = heap.top();
    heap.pop();
    if (cell.zLow >= bestZ - kSlack) break;
    bool tried = cell.tried;
    if (cell.B < kNewtonBound && !tried) {
      double u = 0.5 * (cell.u0 + cell.u1), t = 0.5 * (cell.t0 + cell.t1);
      Vec3 p;
      if (e.newton(cell.k, x, y, ts, u, t, p)) {
        ++st.newtonRoots;
        keep(cell.k, u, t, p);
        // The root is this cell's: its halves need not start Newton again.
        tried = u >= cell.u0 && u <= cell.u1 && t >= cell.t0 && t <= cell.t1;
        if (cell.zLow >= bestZ - kSlack) continue;
      }
    }
    if (cell.B < kLeafBound) {
      double u = 0.5 * (cell.u0 + cell.u1), t = 0.5 * (cell.t0 + cell.t1);
      Vec3 p;
      if (e.newton(cell.k, x, y, ts, u, t, p)) {
        ++st.newtonRoots;
        keep(cell.k, u, t, p);
      } else {
        ++st.nearCrossings;
        keep(cell.k, 0.5 * (cell.u0 + cell.u1), 0.5 * (cell.t0 + cell.t1), cell.p);
      }
      continue;
    }
    // Halve across the larger of the two terms of B.
    const double um = 0.5 * (cell.u0 + cell.u1), tm = 0.5 * (cell.t0 + cell.t1);
    if (e.Lu[size_t(cell.k)] * (cell.u1 - cell.u0) >= e.Lt(cell.u1) * (cell.t1 - cell.t0)) {
      push(cell.k, cell.u0, um, cell.t0, cell.t1, tried);
      push(cell.k, um, cell.u1, cell.t0, cell.t1, tried);
    } else {
      push(cell.k, cell.u0, cell.u1, cell.t0, tm, tried);
      push(cell.k, cell.u0, cell.u1, tm, cell.t1, tried);
    }
  }
  return best;
}

ToothHit toothLowestDense(const Cutter& c, const ToothMove& m, double x, double y, int nu, int nt,
                          double near) {
  const Edges e(c, m);
  ToothHit best;
  double t0, t1;
  if (!e.window(x, y, t0, t1)) return best;
  const double ts = e.Lt(e.U);
  std::vector<double> d(size_t(nu) * size_t(nt));
  auto uAt = [&](int k, int i) {  // tooth k's span in nu samples
    return e.uLo[size_t(k)] + (e.uHi[size_t(k)] - e.uLo[size_t(k)]) * i / (nu - 1);
  };
  for (int k = 0; k < c.teeth.flutes; ++k) {
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nt; ++j) {
        const Vec3 p = e.point(k, uAt(k, i), t0 + (t1 - t0) * j / (nt - 1));
        d[size_t(i) * nt + j] = std::hypot(p.x - x, p.y - y);
      }
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nt; ++j) {
        const double di = d[size_t(i) * nt + j];
        if (di > near) continue;
        bool minimum = true;
        for (int a = std::max(0, i - 1); a <= std::min(nu - 1, i + 1) && minimum; ++a)
          for (int b = std::max(0, j - 1); b <= std::min(nt - 1, j + 1); ++b)
            if (d[size_t(a) * nt + b] < di) minimum = false;
        if (!minimum) continue;
        double u = uAt(k, i), t = t0 + (t1 - t0) * j / (nt - 1);
        Vec3 p;
        if (e.newton(k, x, y, ts, u, t, p) && (!best.hit || p.z < best.z))
          best = {true, p.z, t, u, k};
      }
  }
  return best;
}

namespace {

Cutter withTeeth(Cutter c, int flutes, double helixDeg, double runout, double runoutPhaseDeg) {
  c.teeth = CutterTeeth::make(flutes, helixDeg, runout, runoutPhaseDeg, c.radius);
  return c;
}

// Every root the search reports is on the line and on the edge it names.
void expectOnLine(const Cutter& c, const ToothMove& m, double x, double y, const ToothHit& h) {
  ASSERT_TRUE(h.hit);
  const Vec3 p = toothEdgePoint(c, m, h.tooth, h.u, h.t);
  EXPECT_LE(std::hypot(p.x - x, p.y - y), 1e-11);
  EXPECT_EQ(p.z, h.z);
  EXPECT_GE(h.u, 0);
  EXPECT_LE(h.u, edgeLength(c));
  EXPECT_GE(h.t, 0);
  EXPECT_LE(h.t, 1);
}

// A vertical flat end mill whose tip ramps along X, tip(t) = (v t, 0, s t): every edge
// point that can reach the line below the flank's is on the bottom disc (h = 0), and a
// radial edge of the disc is on the line exactly when the line's angle about the
// cutter's own centre T(t) = tip(t) + runout u(psi_r - phi) is the tooth's,
//     g_k(t) = angle((x, y) - T(t)) - (psi_k - phi(t)) = 0 (mod 2 pi),
// with |(x, y) - T(t)| <= R. (Helix 0: the flank edges are vertical segments over the
// rim, on the line only where the disc's rim is, which is the disc's crossing too.) The
// height is then s t: the closed form is the least s t over the roots of g, found here
// by a scan of t and bisection, one equation in one unknown.
double flatRampClosedForm(const Cutter& c, const ToothMove& m, double x, double y) {
  double best = HUGE_VAL;
  const int n = 100000;
  for (int k = 0; k < c.teeth.flutes; ++k) {
    auto g = [&](double t, double& radius) {
      const double phi = m.phaseStart + m.phaseRate * t;
      const double ang = degToRad(c.teeth.runoutPhaseDeg) - phi;
      // e1 = X, e2 = Y for the vertical axis.
      const double cx = m.p0.x + (m.p1.x - m.p0.x) * t + c.teeth.runout * std::cos(ang);
      const double cy = m.p0.y + (m.p1.y - m.p0.y) * t + c.teeth.runout * std::sin(ang);
      radius = std::hypot(x - cx, y - cy);
      return std::remainder(std::atan2(y - cy, x - cx) - (2 * kPi * k / c.teeth.flutes - phi),
                            2 * kPi);
    };
    double r0;
    double gPrev = g(0, r0);
    for (int i = 1; i <= n; ++i) {
      double rad;
      const double ti = double(i) / n, gi = g(ti, rad);
      // A sign change that is not the wrap at +-pi.
      if ((gPrev <= 0) != (gi <= 0) && std::fabs(gi - gPrev) < kPi) {
        double lo = double(i - 1) / n, hi = ti, glo = gPrev;
        for (int it = 0; it < 100; ++it) {
          const double mid = 0.5 * (lo + hi);
          double rm;
          const double gm = g(mid, rm);
          ((gm <= 0) == (glo <= 0) ? lo : hi) = mid;
        }
        double rr;
        g(0.5 * (lo + hi), rr);
        const double t = 0.5 * (lo + hi);
        if (rr <= c.radius) best = std::min(best, m.p0.z + (m.p1.z - m.p0.z) * t);
      }
      gPrev = gi;
    }
  }
  return best;
}

TEST(ToothReference, FlatEndMillRampAgreesWithTheDiscsClosedForm) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0, misses = 0;
  double worst = 0;
  ToothStats stats;
  for (int n = 0; n < 24; ++n) {
    const int flutes = 1 + n % 4;
    const double runout = n % 2 ? 0.05 * u(rng) : 0;
    const Cutter c =
        withTeeth(Cutter::make(CutterType::Flat, 2, 0, 3), flutes, 0, runout, 360 * u(rng));
    const double fz = 0.05 + 0.15 * u(rng);
    const Vec3 p0{0, 0, 0}, p1{1.5, 0, n % 3 == 0 ? 0.0 : (u(rng) - 0.5)};
    const ToothMove m{
        p0, p1, {0, 0, 1}, {0, 0, 1}, 2 * kPi * u(rng), 2 * kPi * length(p1 - p0) / (flutes * fz)};
    const double x = -1 + 3.5 * u(rng), y = (2 * u(rng) - 1) * 2.1;
    const double want = flatRampClosedForm(c, m, x, y);
    const ToothHit got = toothLowest(c, m, x, y, &stats);
    if (want == HUGE_VAL) {
      EXPECT_FALSE(got.hit) << n;
      ++misses;
      continue;
    }
    expectOnLine(c, m, x, y, got);
    EXPECT_NEAR(got.z, want, 1e-9) << n;
    worst = std::max(worst, std::fabs(got.z - want));
    ++compared;
  }
  std::printf(
      "ToothReference flat ramp: %d compared (worst %.3g mm), %d misses, %ld cells, %ld "
      "near-crossings\n",
      compared, worst, misses, stats.cells, stats.nearCrossings);
  EXPECT_GE(compared, 15);
  EXPECT_EQ(stats.nearCrossings, 0);
}

// A ball with lead lambda along +X (axis (sin, 0, cos)), helix 0, no runout: e1 is the
// downhill direction d = (cos, 0, -sin) (world X made perpendicular to the axis), and
// when tooth k's angle psi_k - phi is 0 its edge is the meridian arc c + R (sin(alpha) d
// - cos(alpha) a), alpha in [0, pi / 2], c = tip + R a, in the plane y = 0: a circle of
// radius R about c. At every other time the edge meets y = 0 only on the axis (its
// half-plane holds the axis, which lies in y = 0), at the tip, R (1 - cos(lambda)) above
// the circle's bottom. So on y = 0 near the bottom the height is the least of
//     c_n.z - sqrt(R^2 - (x - c_n.x)^2)
// over the passes n (phi(t_n) = psi_k mod 2 pi), while |x - c_n.x| <= R cos(lambda).
TEST(ToothReference, BallLeadCentreLineIsTheMeridianArcs) {
  const double R = 3, lambda = degToRad(15), fz = 0.1;
  const int flutes = 2;
  const Cutter c = withTeeth(Cutter::make(CutterType::Ball, R, 0, 4), flutes, 0, 0, 0);
  const Vec3 a{std::sin(lambda), 0, std::cos(lambda)};
  const Vec3 p0{-1, 0, 0}, p1{1, 0, 0};
  const double phi0 = 0.3, rate = 2 * kPi * length(p1 - p0) / (flutes * fz);
  const ToothMove m{p0, p1, a, a, phi0, rate};
  ToothStats stats;
  double worst = 0;
  for (int i = 0; i <= 20; ++i) {
    const double x = -0.3 + 0.6 * i / 20 + 0.0013;
    double want = HUGE_VAL;
    for (int k = 0; k < flutes; ++k) {
      const double psi = 2 * kPi * k / flutes;
      for (int w = -40; w <= 40; ++w) {
        const double t = (psi + 2 * kPi * w - phi0) / rate;
        if (t < 0 || t > 1) continue;
        const Vec3 centre = p0 + (p1 - p0) * t + a * R;
        const double dx = x - centre.x;
        if (std::fabs(dx) <= R * std::cos(lambda))
          want = std::min(want, centre.z - std::sqrt(R * R - dx * dx));
      }
    }
    const ToothHit got = toothLowest(c, m, x, 0, &stats);
    expectOnLine(c, m, x, 0, got);
    EXPECT_NEAR(got.z, want, 1e-9) << x;
    worst = std::max(worst, std::fabs(got.z - want));
  }
  std::printf("ToothReference ball lead arcs: worst %.3g mm, %ld cells\n", worst, stats.cells);
  EXPECT_EQ(stats.nearCrossings, 0);
}

// The subdivision search against the plain grid method on small random moves of every
// kind (bull, ball, flat; helix, runout, tilt, turning, ramps): two methods, one answer.
TEST(ToothReference, SubdivisionAgreesWithADenseGrid) {
  std::mt19937_64 rng(1818);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0;
  double worst = 0;
  for (int n = 0; n < 6; ++n) {
    const CutterType type = n % 3 == 0   ? CutterType::Bull
                            : n % 3 == 1 ? CutterType::Ball
                                         : CutterType::Flat;
    const Cutter c = withTeeth(Cutter::make(type, 1, 0.4, 1.5), 1 + n % 3, 40 * u(rng),
                               0.05 * u(rng), 360 * u(rng));
    const double tilt = 0.6 * u(rng), az = 2 * kPi * u(rng);
    const Vec3 a0{std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt)};
    const Vec3 a1 = n % 2 ? normalize(a0 + Vec3{0.2, -0.1, 0}) : a0;
    const Vec3 p0{0, 0, 0}, p1{0.25, 0.05, -0.05};
    const double fz = 0.08;
    const ToothMove m{
        p0, p1, a0, a1, 2 * kPi * u(rng), 2 * kPi * length(p1 - p0) / (c.teeth.flutes * fz)};
    for (int q = 0; q < 2; ++q) {
      const double x = 0.12 + 0.8 * (u(rng) - 0.5), y = 0.8 * (u(rng) - 0.5);
      const ToothHit a = toothLowest(c, m, x, y);
      const ToothHit b = toothLowestDense(c, m, x, y, 200, 2000, 0.03);
      ASSERT_EQ(a.hit, b.hit) << n << " " << q;
      if (!a.hit) continue;
      expectOnLine(c, m, x, y, a);
      // The grid can only miss roots (it errs upwards), never find a lower one.
      EXPECT_NEAR(a.z, b.z, 1e-9) << n << " " << q;
      worst = std::max(worst, std::fabs(a.z - b.z));
      ++compared;
    }
  }
  std::printf("ToothReference subdivision vs grid: %d compared, worst %.3g mm\n", compared, worst);
  EXPECT_GE(compared, 8);
}

}  // namespace
}  // namespace ref
}  // namespace scallop
