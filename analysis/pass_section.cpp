// The exact section of a pass and its path interval: see pass_section.h for the
// derivation (support map, Lagrange dual bound, chord bound, monotone width).
#include "analysis/pass_section.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "base/constants.h"
#include "sweep/raster.h"
#include "sweep/swept_segment.h"

namespace scallop {

namespace {

constexpr int kMaxBisections = 200;

}  // namespace

PassSection::PassSection(SupportMap support, double centreY, double toleranceMm)
    : support_(std::move(support)), centreY_(centreY), tolerance_(toleranceMm) {
  const Vec3 lowest = support_(Vec3{0, 0, -1});
  floorZ_ = lowest.z;
  floorY_ = lowest.y;
  top_ = support_(Vec3{0, 0, 1}).z;
  reachPlus_ = support_(Vec3{0, 1, 0}).y;
  reachMinus_ = -support_(Vec3{0, -1, 0}).y;
}

PassSection PassSection::of(const Cutter& cutter, double leadDeg, double tiltDeg,
                            double toleranceMm) {
  const Vec3 axis = leadTiltAxis(Vec3{1, 0, 0}, leadDeg, tiltDeg);
  return PassSection([cutter, axis](const Vec3& dir) { return cutterSupport(cutter, axis, dir); },
                     cutter.cornerRadius * axis.y, toleranceMm);
}

SectionSide PassSection::side(double h, int sign) const {
  SectionSide out;
  const double s = sign > 0 ? 1.0 : -1.0;
  const double zh = floorZ_ + h;
  auto support = [&](double phi) { return support_(Vec3{0, s * std::cos(phi), -std::sin(phi)}); };
  // phi_a keeps its support point at or above zh, phi_b below (the floor's, at pi/2).
  double phiA = 0, phiB = 0.5 * kPi;
  Vec3 qa = support(phiA), qb = support_(Vec3{0, 0, -1});
  const double reach = s * qa.y;
  if (!(h > 0) || qa.z < zh) {
    // The face of K farthest along +-y reaches below zh: F stays below h up to the
    // vertical flank of the shadow.
    out.offset = {reach, reach};
    return out;
  }
  // U(phi) = y'(q) + tan(phi) (zh - q_z), the dual bound; +inf at pi/2.
  auto upper = [&](double phi, const Vec3& q) {
    return phi >= 0.5 * kPi ? HUGE_VAL : s * q.y + std::tan(phi) * (zh - q.z);
  };
  double high = std::min(upper(phiA, qa), upper(phiB, qb)), low = -HUGE_VAL;
  for (int iter = 0; iter < kMaxBisections; ++iter) {
    // The chord from qa (z >= zh) to qb (z < zh) meets z = zh inside K.
    const double t = (qa.z - zh) / (qa.z - qb.z);
    low = std::max(low, s * (qa.y + t * (qb.y - qa.y)));
    if (high - low <= tolerance_) break;
    const double mid = 0.5 * (phiA + phiB);
    if (!(mid > phiA && mid < phiB)) break;
    const Vec3 q = support(mid);
    high = std::min(high, upper(mid, q));
    if (q.z >= zh) {
      phiA = mid, qa = q;
    } else {
      phiB = mid, qb = q;
    }
  }
  // phi_a never left 0 and no dual bound came below the flank: the crossing, if any, is
  // within round-off of the vertical flank, which then starts below zh. (A support
  // direction can close the bracket at once: a 90-degree V-bit's face is normal to the
  // first bisection's direction, pi/4, whose bound is then exact, phi_a still 0.)
  out.reachable = phiA > 0 || high < reach - tolerance_;
  out.offset = out.reachable ? Enclosure{low, std::max(low, high)} : Enclosure{reach, reach};
  return out;
}

SectionSide PassSection::sideFromCentre(double h, int sign) const {
  SectionSide out = side(h, sign);
  const double shift = sign > 0 ? -centreY_ : centreY_;
  out.offset.low += shift;
  out.offset.high += shift;
  return out;
}

bool PassSection::stepOver(double h, Enclosure* width) const {
  const SectionSide plus = side(h, +1), minus = side(h, -1);
  *width = {plus.offset.low + minus.offset.low, plus.offset.high + minus.offset.high};
  return plus.reachable && minus.reachable;
}

bool PassSection::scallop(double stepOverMm, double* scallopMm, std::string* reason) const {
  if (!(stepOverMm > 0) || !std::isfinite(stepOverMm)) {
    *reason = "the step-over must be a number > 0 mm";
    return false;
  }
  return coverScallop({{0, false}, {stepOverMm, false}}, floorY_, stepOverMm + floorY_, scallopMm,
                      reason);
}

bool PassSection::coverScallop(const std::vector<PassPlacement>& passes, double fromMm, double toMm,
                               double* scallopMm, std::string* reason) const {
  // Whether the passes' intervals at height h cover [from, to]; `reachable` false if
  // a side is only bounded by its flank there.
  std::vector<std::pair<double, double>> intervals(passes.size());
  auto covers = [&](double h, bool* reachable) {
    const SectionSide plus = side(h, +1), minus = side(h, -1);
    *reachable = plus.reachable && minus.reachable;
    for (size_t k = 0; k < passes.size(); ++k) {
      const double c = passes[k].crossMm;
      const bool m = passes[k].mirrored;
      intervals[k] = {c - (m ? plus : minus).offset.mid(), c + (m ? minus : plus).offset.mid()};
    }
    std::sort(intervals.begin(), intervals.end());
    double reach = fromMm;
    for (const auto& [lo, hi] : intervals) {
      if (lo > reach) break;
      reach = std::max(reach, hi);
    }
    return reach >= toMm;
  };
  bool reachable = false;
  double lo = 0, hi = heightMm();
  if (!covers(hi, &reachable)) {
    *reason = "the passes leave an uncut strip: their shadows do not meet";
    return false;
  }
  for (int iter = 0; iter < kMaxBisections && hi - lo > tolerance_; ++iter) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (covers(mid, &reachable) ? hi : lo) = mid;
  }
  covers(hi, &reachable);
  if (!reachable) {
    *reason =
        "the passes meet on the vertical flank of the cutter's shadow: the cusp is a "
        "wall, not a scallop";
    return false;
  }
  *scallopMm = hi;
  return true;
}

namespace {

std::string checkPosture(double leadDeg, double tiltDeg) {
  if (!std::isfinite(leadDeg) || !std::isfinite(tiltDeg) || std::fabs(leadDeg) >= 90 ||
      std::fabs(tiltDeg) >= 90)
    return "exact: lead " + std::to_string(leadDeg) + " deg and tilt " + std::to_string(tiltDeg) +
           " deg must satisfy |angle| < 90";
  return {};
}

}  // namespace

ProcedureResult halfIntervalExact(const Cutter& cutter, double leadDeg, double tiltDeg,
                                  double scallopHeightMm, double toleranceMm) {
  if (auto why = checkPosture(leadDeg, tiltDeg); !why.empty()) return {false, 0, why};
  if (!(scallopHeightMm > 0) || !std::isfinite(scallopHeightMm))
    return {false, 0, "exact: the scallop height h must be a number > 0 mm"};
  const PassSection section = PassSection::of(cutter, leadDeg, tiltDeg, toleranceMm);
  Enclosure width;
  if (!section.stepOver(scallopHeightMm, &width))
    return {false, 0,
            "exact: h = " + std::to_string(scallopHeightMm) +
                " mm is beyond the cutter: one side of the pass ends at a vertical flank below it"};
  return {true, 0.5 * width.mid(), {}};
}

ProcedureResult scallopHeightExact(const Cutter& cutter, double leadDeg, double tiltDeg,
                                   double halfIntervalMm, double toleranceMm) {
  if (auto why = checkPosture(leadDeg, tiltDeg); !why.empty()) return {false, 0, why};
  const PassSection section = PassSection::of(cutter, leadDeg, tiltDeg, toleranceMm);
  double h = 0;
  std::string reason;
  if (!section.scallop(2 * halfIntervalMm, &h, &reason)) return {false, 0, "exact: " + reason};
  return {true, h, {}};
}

}  // namespace scallop
