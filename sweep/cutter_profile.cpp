// CutterProfile: validation, width, support and signed distance of a convex chain of
// lines and arcs (cutter_profile.h).
//
// Why the 2D signed distance is the 3D one, and convex. K is P swept about the axis;
// mirrored about the axis, P becomes the convex region P2 = P u mirror(P), and K is P2
// revolved. For a point p at (rho, s), rho >= 0, the nearest point of K lies in p's own
// meridian half-plane (rotating any point of K into it, at the same s and distance
// from the axis, brings it no farther from p), so the distance from p to K is the 2D
// distance from (rho, s) to P2, and likewise the depth of an inside point is its 2D
// distance to P2's boundary. A point of the mirror half is never nearer than its own
// mirror image, so for rho >= 0 only P's boundary counts: the chain and the cap s = L
// (the axis is not boundary: P2 continues across it). The signed distance to a convex
// set is convex, so sd(|p_perp|, s) is the (convex) signed distance from p to K, and
// its gradient is the outward unit normal of the nearest boundary point.
//
// Every piece is a closed form: a segment's nearest point is the clamped projection;
// an arc's is the radial projection from its centre where that lies in the arc's
// sector, else an end.
#include "sweep/cutter_profile.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"
#include "sweep/cutter.h"

namespace scallop {

namespace {

constexpr double kJoinSlack = 1e-9;  // mm: ends closer than this are the same point
constexpr double kTurnSlack = 1e-9;  // rad: a turn away from the solid this small is none

double crossRhoS(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}

// The tangent angle (from +rho towards +s) where a segment starts (`atEnd` false) or ends.
double tangentAngle(const ProfileSegment& g, bool atEnd) {
  if (g.arcRadius > 0) {
    // Arcs run anticlockwise about their centre (the solid on their left), so the
    // tangent is the radius turned a quarter anticlockwise.
    const double r = atEnd ? g.rho1 : g.rho0, s = atEnd ? g.s1 : g.s0;
    return std::atan2(s - g.centreS, r - g.centreRho) + kPi / 2;
  }
  return std::atan2(g.s1 - g.s0, g.rho1 - g.rho0);
}

// Whether the direction (dRho, dS) from an arc's centre lies within the arc's sector
// (arcs span at most a half turn).
bool inSector(const ProfileSegment& g, double dRho, double dS) {
  const double ar = g.rho0 - g.centreRho, as = g.s0 - g.centreS;
  const double br = g.rho1 - g.centreRho, bs = g.s1 - g.centreS;
  return crossRhoS(ar, as, dRho, dS) >= 0 && crossRhoS(dRho, dS, br, bs) >= 0 &&
         dRho * (ar + br) + dS * (as + bs) > 0;
}

}  // namespace

CutterProfile CutterProfile::make(std::vector<ProfileSegment> chain, const std::string& field) {
  if (chain.empty()) throw InputError(field, "needs at least one segment from the tip up");
  auto where = [&](size_t i) { return field + "[" + std::to_string(i) + "]"; };
  double prevRho = 0, prevS = 0;
  for (size_t i = 0; i < chain.size(); ++i) {
    ProfileSegment& g = chain[i];
    for (double v : {g.rho0, g.s0, g.rho1, g.s1, g.arcRadius})
      if (!std::isfinite(v) || std::fabs(v) > 4e6)
        throw InputError(where(i), "every coordinate and radius must be a finite number of mm");
    if (std::hypot(g.rho0 - prevRho, g.s0 - prevS) > kJoinSlack)
      throw InputError(
          where(i), "starts at (" + formatNumber(g.rho0) + ", " + formatNumber(g.s0) +
                        ") mm, not " + (i == 0 ? "at the tip (0, 0)" : "where the previous ends") +
                        " (" + formatNumber(prevRho) + ", " + formatNumber(prevS) + ")");
    g.rho0 = prevRho, g.s0 = prevS;
    if (g.rho1 < -kJoinSlack)
      throw InputError(where(i), "ends at rho = " + formatNumber(g.rho1) + " mm, across the axis");
    g.rho1 = std::max(0.0, g.rho1);
    const double chord = std::hypot(g.rho1 - g.rho0, g.s1 - g.s0);
    if (!(chord > kJoinSlack)) throw InputError(where(i), "has zero length");
    if (g.arcRadius < 0)
      throw InputError(where(i), "an arc radius must be > 0 mm (0: a straight line), got " +
                                     formatNumber(g.arcRadius));
    if (g.arcRadius > 0) {
      if (chord > 2 * g.arcRadius * (1 + 1e-12))
        throw InputError(where(i), "an arc of radius " + formatNumber(g.arcRadius) +
                                       " mm cannot join ends " + formatNumber(chord) + " mm apart");
      // The centre on the solid's side (left of the chord, walking from the tip up).
      const double h = std::sqrt(std::max(0.0, g.arcRadius * g.arcRadius - 0.25 * chord * chord));
      const double ur = (g.rho1 - g.rho0) / chord, us = (g.s1 - g.s0) / chord;
      g.centreRho = 0.5 * (g.rho0 + g.rho1) - us * h;
      g.centreS = 0.5 * (g.s0 + g.s1) + ur * h;
    }
    prevRho = g.rho1, prevS = g.s1;
  }
  // Convexity: the tangent starts between outwards and up, only ever turns towards the
  // solid (anticlockwise), and ends no further round than the cap's (pointing inwards).
  double before = tangentAngle(chain[0], false);
  if (before < -kTurnSlack || before > kPi / 2 + kTurnSlack)
    throw InputError(where(0), "must leave the tip outwards or upwards (no spike below the tip)");
  for (size_t i = 0; i < chain.size(); ++i) {
    const double start = tangentAngle(chain[i], false), end = tangentAngle(chain[i], true);
    if (start < before - kTurnSlack)
      throw InputError(where(i),
                       "turns away from the solid where it starts (the profile must "
                       "be convex)");
    if (end > kPi + kTurnSlack)
      throw InputError(where(i),
                       "turns down past the horizontal (the profile must be convex "
                       "and closed by the flat top)");
    before = end;
  }
  if (!(prevS > 0)) throw InputError(where(chain.size() - 1), "must end above the tip (s > 0)");
  return fromChain(std::move(chain));
}

CutterProfile CutterProfile::fromChain(std::vector<ProfileSegment> chain) {
  CutterProfile p;
  p.segments_ = std::move(chain);
  p.startAngle_.reserve(p.segments_.size());
  p.endAngle_.reserve(p.segments_.size());
  for (const ProfileSegment& g : p.segments_) {
    p.startAngle_.push_back(tangentAngle(g, false));
    p.endAngle_.push_back(tangentAngle(g, true));
  }
  p.fluteLength_ = p.segments_.back().s1;
  p.maxRadius_ = p.support(1, 0).rho;
  p.bottomRadius_ = p.width(0);
  p.reach_ = std::hypot(p.fluteLength_, p.maxRadius_);
  return p;
}

CutterProfile CutterProfile::of(const Cutter& cutter) {
  if (cutter.profile) return *cutter.profile;
  const double R = cutter.radius, r = cutter.cornerRadius, Rb = R - r, L = cutter.fluteLength;
  std::vector<ProfileSegment> chain;
  if (Rb > 0) chain.push_back({0, 0, Rb, 0});
  if (r > 0) chain.push_back({Rb, 0, R, r, r, Rb, r});  // the corner's centre, exactly
  if (L > r) chain.push_back({R, r, R, L});
  return fromChain(std::move(chain));
}

double CutterProfile::width(double s) const {
  if (!(s >= 0 && s <= fluteLength_)) return 0;
  double w = 0;
  for (const ProfileSegment& g : segments_) {
    if (s < g.s0 || s > g.s1) continue;
    double rho;
    if (g.s1 == g.s0) {
      rho = std::max(g.rho0, g.rho1);
    } else if (g.arcRadius > 0) {
      const double ds = s - g.centreS;
      rho = g.centreRho + std::sqrt(std::max(0.0, (g.arcRadius - ds) * (g.arcRadius + ds)));
    } else {
      rho = g.rho0 + (g.rho1 - g.rho0) * ((s - g.s0) / (g.s1 - g.s0));
    }
    w = std::max(w, rho);
  }
  return w;
}

ProfilePoint CutterProfile::support(double nRho, double nS) const {
  ProfilePoint best{0, 0};
  double bestValue = 0;
  auto consider = [&](double rho, double s) {
    const double v = nRho * rho + nS * s;
    if (v > bestValue) best = {rho, s}, bestValue = v;
  };
  for (const ProfileSegment& g : segments_) {
    consider(g.rho1, g.s1);
    if (g.arcRadius > 0 && inSector(g, nRho, nS)) {
      const double len = std::hypot(nRho, nS);
      consider(g.centreRho + g.arcRadius * nRho / len, g.centreS + g.arcRadius * nS / len);
    }
  }
  return best;
}

namespace {

// The nearest point of one boundary piece to (rho, s), its squared distance, and the
// piece's outward normal there. Inside a piece that normal is the distance's gradient,
// and far more accurate than (p - q) / d near the boundary, where d is all round-off;
// at a piece's end (`corner`) the gradient is (p - q) / d, any normal of the corner's.
struct NearestOnProfile {
  double d2 = HUGE_VAL, rho = 0, s = 0, nRho = 0, nS = 0;
  bool corner = false;
};

void nearestOnLine(double r0, double s0, double r1, double s1, double rho, double s,
                   NearestOnProfile& best) {
  const double dr = r1 - r0, ds = s1 - s0, len2 = dr * dr + ds * ds;
  double u = len2 > 0 ? ((rho - r0) * dr + (s - s0) * ds) / len2 : 0;
  u = std::clamp(u, 0.0, 1.0);
  const double qr = r0 + u * dr, qs = s0 + u * ds;
  const double d2 = (rho - qr) * (rho - qr) + (s - qs) * (s - qs);
  if (d2 < best.d2) {
    const double len = std::sqrt(len2);
    // The tangent turned clockwise: outwards.
    best = {d2, qr, qs, ds / len, -dr / len, u == 0 || u == 1};
  }
}

void nearestOnArc(const ProfileSegment& g, double rho, double s, NearestOnProfile& best) {
  const double dr = rho - g.centreRho, ds = s - g.centreS, len = std::hypot(dr, ds);
  if (len > 0 && inSector(g, dr, ds)) {
    const double qr = g.centreRho + g.arcRadius * dr / len, qs = g.centreS + g.arcRadius * ds / len;
    const double d = len - g.arcRadius;
    if (d * d < best.d2) best = {d * d, qr, qs, dr / len, ds / len, false};
    return;
  }
  for (int end = 0; end < 2; ++end) {
    const double qr = end ? g.rho1 : g.rho0, qs = end ? g.s1 : g.s0;
    const double d2 = (rho - qr) * (rho - qr) + (s - qs) * (s - qs);
    if (d2 < best.d2)
      best = {d2, qr, qs, (qr - g.centreRho) / g.arcRadius, (qs - g.centreS) / g.arcRadius, true};
  }
}

}  // namespace

double CutterProfile::signedDistance(double rho, double s, double* dRho, double* dS) const {
  NearestOnProfile best;
  for (const ProfileSegment& g : segments_) {
    if (g.arcRadius > 0)
      nearestOnArc(g, rho, s, best);
    else
      nearestOnLine(g.rho0, g.s0, g.rho1, g.s1, rho, s, best);
  }
  const ProfileSegment& last = segments_.back();
  if (last.rho1 > 0) nearestOnLine(last.rho1, last.s1, 0, last.s1, rho, s, best);
  const double d = std::sqrt(best.d2);
  const bool in = s >= 0 && s <= fluteLength_ && rho <= width(s);
  if (dRho || dS) {
    double gr = best.nRho, gs = best.nS;
    if (best.corner && d > 0) {
      gr = (rho - best.rho) / d, gs = (s - best.s) / d;
      if (in) gr = -gr, gs = -gs;
    }
    if (dRho) *dRho = gr;
    if (dS) *dS = gs;
  }
  return in ? -d : d;
}

CutterProfile CutterProfile::grown(double delta) const {
  // In the frame of a tip delta lower: every point moves up by delta first.
  std::vector<ProfileSegment> out;
  auto normalR = [](double angle) { return std::sin(angle); };
  auto normalS = [](double angle) { return -std::cos(angle); };
  // A corner of the chain at (vr, vs) (old frame) becomes an arc of radius delta round
  // it, from the outward normal of tangent angle a0 to that of a1 (a1 > a0).
  auto corner = [&](double vr, double vs, double a0, double a1) {
    if (!(a1 > a0)) return;
    ProfileSegment g;
    g.rho0 = vr + delta * normalR(a0), g.s0 = vs + delta + delta * normalS(a0);
    g.rho1 = vr + delta * normalR(a1), g.s1 = vs + delta + delta * normalS(a1);
    if (g.rho0 == g.rho1 && g.s0 == g.s1) return;
    g.arcRadius = delta, g.centreRho = vr, g.centreS = vs + delta;
    out.push_back(g);
  };
  corner(0, 0, 0, startAngle_[0]);  // the tip: from straight down to the first normal
  for (size_t i = 0; i < segments_.size(); ++i) {
    const ProfileSegment& g = segments_[i];
    if (i > 0) corner(g.rho0, g.s0, endAngle_[i - 1], startAngle_[i]);
    ProfileSegment o = g;
    if (g.arcRadius > 0) {
      const double k = (g.arcRadius + delta) / g.arcRadius;
      o.arcRadius = g.arcRadius + delta;
      o.centreS = g.centreS + delta;
      o.rho0 = g.centreRho + (g.rho0 - g.centreRho) * k;
      o.s0 = o.centreS + (g.s0 - g.centreS) * k;
      o.rho1 = g.centreRho + (g.rho1 - g.centreRho) * k;
      o.s1 = o.centreS + (g.s1 - g.centreS) * k;
    } else {
      const double a = startAngle_[i];
      o.rho0 = g.rho0 + delta * normalR(a), o.s0 = g.s0 + delta + delta * normalS(a);
      o.rho1 = g.rho1 + delta * normalR(a), o.s1 = g.s1 + delta + delta * normalS(a);
    }
    out.push_back(o);
  }
  const ProfileSegment& last = segments_.back();
  corner(last.rho1, last.s1, endAngle_.back(), kPi);  // up to the cap's normal
  // Each piece starts where the previous ended, to round-off: make it exact.
  out.front().rho0 = 0, out.front().s0 = 0;
  for (size_t i = 1; i < out.size(); ++i) out[i].rho0 = out[i - 1].rho1, out[i].s0 = out[i - 1].s1;
  return fromChain(std::move(out));
}

CutterProfile CutterProfile::widened(double dRho) const {
  if (dRho == 0) return *this;
  std::vector<ProfileSegment> out;
  const double bottom = bottomRadius_ + dRho;
  // The flat bottom from the axis, if any is left.
  if (bottom > 0) out.push_back({0, 0, bottom, 0});
  for (const ProfileSegment& g : segments_) {
    if (g.s0 == 0 && g.s1 == 0) continue;  // the old flat bottom
    ProfileSegment o = g;
    o.rho0 += dRho, o.rho1 += dRho;
    if (g.arcRadius > 0) o.centreRho += dRho;
    out.push_back(o);
  }
  // The bottom's end is the first piece's start, exactly.
  if (out.size() > 1 && bottom > 0) out[1].rho0 = bottom, out[1].s0 = 0;
  if (bottom <= 0) out.front().rho0 = 0, out.front().s0 = 0;
  return fromChain(std::move(out));
}

// --- Arc length along the chain (edge spans) ---------------------------------------
// A segment is a line or an arc of at most a half turn; on an arc, angles are taken
// about its centre from +rho towards +s, and `sweep` is the signed turn from start to end.

namespace {

struct ArcAngles {
  double start, sweep;
};
ArcAngles arcAngles(const ProfileSegment& g) {
  const double a0 = std::atan2(g.s0 - g.centreS, g.rho0 - g.centreRho);
  const double a1 = std::atan2(g.s1 - g.centreS, g.rho1 - g.centreRho);
  return {a0, std::remainder(a1 - a0, 2 * kPi)};
}

double segmentLength(const ProfileSegment& g) {
  const double chord = std::hypot(g.rho1 - g.rho0, g.s1 - g.s0);
  if (!(g.arcRadius > 0)) return chord;
  return 2 * g.arcRadius * std::asin(std::min(1.0, chord / (2 * g.arcRadius)));
}

// The point at arc length l (0 <= l <= its length) along segment g.
ProfilePoint segmentPoint(const ProfileSegment& g, double l) {
  if (!(g.arcRadius > 0)) {
    const double len = segmentLength(g), t = len > 0 ? l / len : 0;
    return {g.rho0 + t * (g.rho1 - g.rho0), g.s0 + t * (g.s1 - g.s0)};
  }
  const ArcAngles a = arcAngles(g);
  const double angle = a.start + std::copysign(l / g.arcRadius, a.sweep);
  return {g.centreRho + g.arcRadius * std::cos(angle), g.centreS + g.arcRadius * std::sin(angle)};
}

// The arc length along g to its point nearest (rho, s), and that point's distance.
void nearestOnSegment(const ProfileSegment& g, double rho, double s, double* along,
                      double* distance) {
  const double len = segmentLength(g);
  if (!(g.arcRadius > 0)) {
    const double dr = g.rho1 - g.rho0, ds = g.s1 - g.s0;
    const double t =
        len > 0 ? std::clamp(((rho - g.rho0) * dr + (s - g.s0) * ds) / (len * len), 0.0, 1.0) : 0;
    *along = t * len;
    *distance = std::hypot(rho - g.rho0 - t * dr, s - g.s0 - t * ds);
    return;
  }
  const ArcAngles a = arcAngles(g);
  const double turn =
      std::remainder(std::atan2(s - g.centreS, rho - g.centreRho) - a.start, 2 * kPi);
  if (turn * a.sweep >= 0 && std::fabs(turn) <= std::fabs(a.sweep)) {
    *along = std::fabs(turn) * g.arcRadius;
    *distance = std::fabs(std::hypot(rho - g.centreRho, s - g.centreS) - g.arcRadius);
    return;
  }
  const double d0 = std::hypot(rho - g.rho0, s - g.s0), d1 = std::hypot(rho - g.rho1, s - g.s1);
  *along = d0 <= d1 ? 0 : len;
  *distance = std::min(d0, d1);
}

}  // namespace

double CutterProfile::arcLength() const {
  double sum = 0;
  for (const ProfileSegment& g : segments_) sum += segmentLength(g);
  return sum;
}

double CutterProfile::arcLengthAt(double rho, double s) const {
  double before = 0, best = HUGE_VAL, at = 0;
  for (const ProfileSegment& g : segments_) {
    double along, distance;
    nearestOnSegment(g, rho, s, &along, &distance);
    if (distance < best) best = distance, at = before + along;
    before += segmentLength(g);
  }
  return at;
}

ProfilePoint CutterProfile::pointAt(double u) const {
  double before = 0;
  for (const ProfileSegment& g : segments_) {
    const double len = segmentLength(g);
    if (u <= before + len) return segmentPoint(g, std::max(0.0, u - before));
    before += len;
  }
  const ProfileSegment& last = segments_.back();
  return {last.rho1, last.s1};
}

void CutterProfile::radiusRange(double from, double to, double* lo, double* hi) const {
  *lo = HUGE_VAL, *hi = -HUGE_VAL;
  double before = 0;
  for (const ProfileSegment& g : segments_) {
    const double len = segmentLength(g);
    const double l0 = std::max(from - before, 0.0), l1 = std::min(to - before, len);
    before += len;
    if (l0 > l1) continue;
    for (double l : {l0, l1}) {
      const double r = segmentPoint(g, l).rho;
      *lo = std::min(*lo, r), *hi = std::max(*hi, r);
    }
    if (!(g.arcRadius > 0)) continue;
    // An arc's farthest and nearest points from the axis, where its sub-arc holds them.
    const ArcAngles a = arcAngles(g);
    for (double extreme : {0.0, kPi}) {
      const double turn = std::remainder(extreme - a.start, 2 * kPi);
      const double l = std::fabs(turn) * g.arcRadius;
      if (turn * a.sweep >= 0 && std::fabs(turn) <= std::fabs(a.sweep) && l >= l0 && l <= l1) {
        const double r = g.centreRho + g.arcRadius * std::cos(extreme);
        *lo = std::min(*lo, r), *hi = std::max(*hi, r);
      }
    }
  }
}

}  // namespace scallop
