#include "analysis/feed_mark_formula.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/constants.h"

namespace scallop {

double circularMarkHeight(double rho, double chord) {
  return rho - std::sqrt(rho * rho - 0.25 * chord * chord);
}

double runoutThreshold(double rho, double leadDeg, double fz) {
  const double lambda = std::fabs(leadDeg) * kPi / 180;
  const double s = std::sin(lambda), c = std::cos(lambda);
  // The positive root of 4 c^2 x^2 + 4 rho s x - fz^2 = 0 (dz = the right-hand side).
  return (-rho * s + std::sqrt(rho * rho * s * s + fz * fz * c * c)) / (2 * c * c);
}

namespace {

FeedMarkPrediction notCovered(const std::string& reason) {
  FeedMarkPrediction p;
  p.reason = reason;
  return p;
}

}  // namespace

FeedMarkPrediction predictFeedMarks(const Cutter& cutter, double leadDeg, double tiltDeg,
                                    double fz) {
  if (cutter.type == CutterType::Flat)
    return notCovered("a flat end mill's corner is sharp (rho_f = 0): its marks are not arcs");
  if (!(std::fabs(leadDeg) > 0) || !(std::fabs(leadDeg) < 90))
    return notCovered(
        "needs a lead 0 < |lead| < 90 deg: without one the contact is at the tip, "
        "on the axis, where every tooth passes");
  if (tiltDeg != 0) return notCovered("derived for lead alone (tilt 0)");
  const double rho = cutter.type == CutterType::Ball ? cutter.radius : cutter.cornerRadius;
  if (!(fz > 0) || !(fz < 2 * rho)) {
    std::ostringstream msg;
    msg << "needs 0 < fz < 2 rho_f = " << 2 * rho << " mm";
    return notCovered(msg.str());
  }
  const CutterTeeth& teeth = cutter.teeth;
  FeedMarkPrediction p;
  p.applicable = true;
  p.profileRadiusMm = rho;
  p.spacingMm = fz;
  p.hasRunoutThreshold = teeth.flutes == 2;
  if (p.hasRunoutThreshold) p.runoutThresholdMm = runoutThreshold(rho, leadDeg, fz);
  if (teeth.runout == 0) {
    p.regime = "no runout";
  } else {
    const double phase = std::fmod(std::fabs(teeth.runoutPhaseDeg), 180.0);
    if (teeth.flutes != 2 || phase != 0 || teeth.helixDeg != 0)
      return notCovered("runout is derived for 2 flutes, runout phase 0 or 180 deg, no helix");
    const double lambda = std::fabs(leadDeg) * kPi / 180;
    const double dz = 2 * teeth.runout * std::sin(lambda);
    const double sigma = 2 * teeth.runout * std::cos(lambda);
    if (teeth.runout >= p.runoutThresholdMm) {
      p.regime = "one tooth cuts";
      p.spacingMm = 2 * fz;
    } else {
      p.regime = "both teeth cut";
      double top = 0;
      for (const double d : {fz - sigma, fz + sigma}) {
        const double x = (2 * rho * dz + d * d) / (2 * d);
        top = std::max(top, x * x / (2 * rho));
      }
      p.heightMm = p.heightParabolaMm = top;
      return p;
    }
  }
  p.heightMm = circularMarkHeight(rho, p.spacingMm);
  p.heightParabolaMm = p.spacingMm * p.spacingMm / (8 * rho);
  return p;
}

}  // namespace scallop
