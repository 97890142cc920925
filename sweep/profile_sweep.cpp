// Kelley's cutting-plane method on the convex f(t) of a constant-axis move of a general
// cutter: the derivation is in profile_sweep.h.
#include "sweep/profile_sweep.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sweep/certified_search.h"
#include "sweep/profile_lowest_point.h"

namespace scallop {

namespace {

constexpr int kKelleySamples = 40;
// Normals closer to horizontal than this give lines too steep to trust round-off with.
constexpr double kKelleyMinNormalZ = 1e-6;

// A proven lower bound of f on [0, 1]: f(t) >= at0 + slope t.
struct KelleyLine {
  double at0, slope;
  double at(double t) const { return at0 + slope * t; }
};

// max over `lines` at t.
double kelleyLargestAt(const std::vector<KelleyLine>& lines, double t) {
  double best = -HUGE_VAL;
  for (const KelleyLine& line : lines) best = std::max(best, line.at(t));
  return best;
}

}  // namespace

ProfileSweepResult profileSweepLowestPoint(const CutterProfile& profile, const Vec3& a,
                                           const Vec3& p0, const Vec3& p1, double x, double y,
                                           double cutoff) {
  const Vec3 d = p1 - p0;
  const double scale = 1 + profile.reach() + std::fabs(x) + std::fabs(y) + length(p0) + length(d);
  // Round-off of the few products in a line or a separation, mm.
  const double slack = 1e-12 * scale;
  std::vector<KelleyLine> lines;
  double lo = 0, hi = 1;  // what is left of [0, 1]
  LowestPoint best;       // the smallest f sampled (U)
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
      lines.push_back({(h + dot(n, p0) - n.x * x - n.y * y) / n.z - margin, dot(n, d) / n.z});
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
    // The minimiser of the largest line over [lo, hi]: an end or where a falling line
    // meets a rising one.
    double next = 0.5 * (lo + hi), bound = -HUGE_VAL;
    if (!lines.empty()) {
      auto consider = [&](double s) {
        const double v = kelleyLargestAt(lines, s);
        if (v < bound || bound == -HUGE_VAL) bound = v, next = s;
      };
      consider(lo), consider(hi);
      for (const KelleyLine& fall : lines)
        for (const KelleyLine& rise : lines)
          if (fall.slope < 0 && rise.slope > 0) {
            const double s = (fall.at0 - rise.at0) / (rise.slope - fall.slope);
            if (s > lo && s < hi) consider(s);
          }
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
