// Kelley's cutting-plane method on the convex f(t) of a constant-axis move of a general
// cutter: the derivation is in profile_sweep.h.
#include "sweep/profile_sweep.h"

#include <algorithm>
#include <cmath>

#include "sweep/certified_search.h"
#include "sweep/profile_lowest_point.h"

namespace scallop {

namespace {

constexpr int kKelleySamples = 40;
// Normals closer to horizontal than this give lines too steep to trust round-off with.
constexpr double kKelleyMinNormalZ = 1e-6;

// A proven lower bound of f on [0, 1]: f(t) >= at0 + slope t.
struct KelleyLine {
  double at0 = 0, slope = 0;
  double t = -1;  // where it touches f; < 0: none yet
  double at(double s) const { return at0 + slope * s; }
};

}  // namespace

ProfileSweepResult profileSweepLowestPoint(const CutterProfile& profile, const Vec3& a,
                                           const Vec3& p0, const Vec3& p1, double x, double y,
                                           double cutoff) {
  const Vec3 d = p1 - p0;
  const double scale = 1 + profile.reach() + std::fabs(x) + std::fabs(y) + length(p0) + length(d);
  // Round-off of the few products in a line or a separation, mm.
  const double slack = 1e-12 * scale;
  // The tangent lines nearest the minimum from either side: falling (slope < 0) at the
  // largest t, rising at the smallest (the others lie below them near the minimum; any
  // subset of the lines is still a lower bound).
  KelleyLine fall, rise;
  int secantSteps = 0;
  KelleyLine last, beforeLast;  // the last two lines sampled
  double lo = 0, hi = 1;        // what is left of [0, 1]
  LowestPoint best;             // the smallest f sampled (U)
  ProfileSweepResult out;
  const double dxy2 = d.x * d.x + d.y * d.y;
  // First where l is nearest the tip's horizontal path.
  double t = dxy2 > 0 ? std::clamp(((x - p0.x) * d.x + (y - p0.y) * d.y) / dxy2, 0.0, 1.0) : 0.5;
  for (int sample = 0; sample < kKelleySamples; ++sample) {
    const Vec3 tip = p0 + d * t;
    LowestPoint f = profileLowestPoint(profile, a, x - tip.x, y - tip.y);
    if (f.hit) {
      f.z += tip.z, f.t = t;
      if (!best.hit || f.z < best.z) best = f;
      const Vec3 n = f.normal;
      if (!(n.z < -kKelleyMinNormalZ)) return out;
      const double h = dot(profileSupport(profile, a, n), n);
      const double margin = slack / -n.z;
      const KelleyLine line{(h + dot(n, p0) - n.x * x - n.y * y) / n.z - margin, dot(n, d) / n.z,
                            t};
      beforeLast = last, last = line;
      if (line.slope < 0) {
        if (fall.t < 0 || t > fall.t) fall = line;
      } else if (rise.t < 0 || t < rise.t) {
        rise = line;
      }
    } else {
      // A horizontal direction separating l from K(t): from the axis' middle, then from
      // the support point in the last direction tried (the nearest point, in the limit).
      const Vec3 w{x - tip.x, y - tip.y, 0};
      const Vec3 mid = a * (0.5 * profile.fluteLength());
      Vec3 m{w.x - mid.x, w.y - mid.y, 0};
      bool separated = false;
      double gap = 0;
      for (int tries = 0; tries < 32 && !separated; ++tries) {
        if (!(length(m) > 0)) break;
        m = m / length(m);
        const Vec3 s = profileSupport(profile, a, m);
        gap = dot(m, w) - dot(m, s);
        if (gap > slack) {
          separated = true;
        } else {
          // Halfway towards the direction from the support point (a full step can
          // swing between two faces of the projection).
          Vec3 toward{w.x - s.x, w.y - s.y, 0};
          const double len = length(toward);
          if (!(len > 0)) break;
          m = tries < 4 ? toward : m + toward / len;
        }
      }
      if (!separated) return out;
      // Every t' with m . (x, y) - m . tip(t') - h(m) > slack misses too: gap - (t' - t) m.d.
      const double md = m.x * d.x + m.y * d.y;
      if (md > 0) {
        lo = std::max(lo, t + (gap - slack) / md);
      } else if (md < 0) {
        hi = std::min(hi, t + (gap - slack) / md);
      } else {
        lo = 1, hi = 0;
      }
    }
    if (!(lo <= hi)) {  // l misses the whole move (or what is left lies above U)
      out.decided = true;
      if (best.hit && best.z < cutoff) out.point = best;
      return out;
    }
    // The lower bound over [lo, hi]: the minimum of the larger of the two lines, where
    // they cross (kept in [lo, hi]) or at the end a single line falls or rises towards.
    double cross = 0.5 * (lo + hi), bound = -HUGE_VAL;
    if (fall.t >= 0 && rise.t >= 0) {
      const double s = (fall.at0 - rise.at0) / (rise.slope - fall.slope);
      cross = std::clamp(std::isfinite(s) ? s : cross, lo, hi);
      bound = std::max(fall.at(cross), rise.at(cross));
    } else if (fall.t >= 0) {
      cross = hi, bound = fall.at(hi);
    } else if (rise.t >= 0) {
      cross = lo, bound = rise.at(lo);
    }
    double next = cross;
    // Newton's method on f' with the secant of the two slopes (superlinear where f is
    // smooth), inside the bracket; every third step the crossing, which shrinks the gap
    // where the secant would keep one end.
    if (fall.t >= 0 && rise.t >= 0 && ++secantSteps % 3 != 0) {
      const double s = fall.t - fall.slope * (rise.t - fall.t) / (rise.slope - fall.slope);
      if (s > fall.t && s < rise.t && s >= lo && s <= hi) next = s;
    } else if (last.t >= 0 && (fall.t < 0 || rise.t < 0)) {
      // One side only: the secant of the last two slopes extrapolated, or from one
      // sample Newton with f'' guessed as |d_xy|^2 / maxRadius (a ball's at its
      // bottom); either way kept in [lo, hi], and the bracket then takes over.
      const double curvature = beforeLast.t >= 0 && last.t != beforeLast.t
                                   ? (last.slope - beforeLast.slope) / (last.t - beforeLast.t)
                                   : dxy2 / profile.maxRadius();
      const double s = last.t - last.slope / curvature;
      if (curvature > 0 && std::isfinite(s)) next = std::clamp(s, lo, hi);
    }
    if (bound >= cutoff) {
      out.decided = true;  // a miss below the cutoff
      return out;
    }
    if (best.hit && best.z - bound <= kProofGap) {
      out.decided = true;
      if (best.z < cutoff) out.point = best;
      return out;
    }
    t = next;
  }
  return out;
}

}  // namespace scallop
