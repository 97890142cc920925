#include "analysis/feed_mark_formula.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/contact_curvature.h"
#include "analysis/feed_marks.h"
#include "analysis/tooth_mark_envelope.h"
#include "base/constants.h"

namespace scallop {

double circularMarkHeight(double rho, double chord) {
  return rho - std::sqrt(rho * rho - 0.25 * chord * chord);
}

double runoutThreshold(double rho, double leadDeg, double fz) {
  const double lambda = degToRad(std::fabs(leadDeg));
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

// Runout, unequal pitch or a tooth offset: anything that makes the teeth's marks differ.
bool hasToothErrors(const CutterTeeth& teeth) {
  if (teeth.runout != 0 || !teeth.toothAnglesDeg().empty()) return true;
  for (const ToothOffset& o : teeth.toothOffsets())
    if (o.radial != 0 || o.axial != 0) return true;
  return false;
}

// Edge spans: which teeth leave their arc at the contact. Each arc's part in the marks
// lies within half a revolution's feed P / 2 of its bottom along the feed, plus the
// farthest any tooth's errors move a bottom (|sigma_k|): on the profile, the arc lengths
// u_c -+ rho_f asin(that / rho_f) around the contact's u_c. A tooth whose span covers
// that stretch leaves its whole arc; one whose span misses it leaves none there (the
// rest of its edge lies on the convex profile above, and the teeth that cut repeat
// within P / 2 of every point, lower); a span that ends inside it leaves a piece of an
// arc, which the envelope of whole arcs does not describe.
struct SpanCheck {
  std::vector<int> teeth;  // the teeth whose arc is whole at the contact
  std::string reason;      // set when a span ends within the marks
};
SpanCheck teethAtContact(const Cutter& cutter, const ContactArc& arc, double lambda,
                         const std::vector<ToothMark>& marks, double period) {
  const CutterTeeth& teeth = cutter.teeth;
  SpanCheck check;
  double shift = 0;
  for (int k = 0; k < teeth.flutes; ++k)
    shift = std::max(
        shift, std::fabs(marks[size_t(k)].positionMm - period * teeth.toothAngle(k) / (2 * kPi)));
  const double rho = arc.radius;
  const double halfArc = rho * std::asin(std::min(1.0, (0.5 * period + shift) / rho));
  const double contactRho = arc.centreRho + rho * std::sin(lambda);
  const double contactHeight = arc.centreS - rho * std::cos(lambda);
  const double uc = cutter.edgeArcLength(contactHeight, contactRho);
  for (int k = 0; k < teeth.flutes; ++k) {
    if (teeth.edgeSpans().empty()) {
      check.teeth.push_back(k);
      continue;
    }
    const EdgeSpan& span = teeth.edgeSpans()[size_t(k)];
    if (span.from <= uc - halfArc && uc + halfArc <= span.to) {
      check.teeth.push_back(k);
    } else if (span.to > uc - halfArc && span.from < uc + halfArc) {
      std::ostringstream msg;
      msg << "tooth " << k + 1 << "'s edge span [" << span.from << ", " << span.to
          << "] mm ends within its marks (the contact at " << uc << " mm -+ " << halfArc
          << " mm of the profile)";
      check.reason = msg.str();
      return check;
    }
  }
  if (check.teeth.empty()) check.reason = "no tooth's edge span covers the contact";
  return check;
}

}  // namespace

std::vector<ToothMark> toothMarks(const CutterTeeth& teeth, double cutterRadiusMm,
                                  double contactHeightMm, double leadRad, double fz) {
  const double s = std::sin(leadRad), c = std::cos(leadRad);
  const double period = teeth.flutes * fz;
  const double helixTurn = contactHeightMm * std::tan(degToRad(teeth.helixDeg)) / cutterRadiusMm;
  std::vector<ToothMark> marks;
  for (int k = 0; k < teeth.flutes; ++k) {
    const double psi = teeth.toothAngle(k);
    const ToothOffset o = teeth.toothOffset(k);
    // The tooth's edge at the contact, moved along r (away from the axis) and along -a.
    const double along =
        teeth.runout * std::cos(degToRad(teeth.runoutPhaseDeg) - psi - helixTurn) + o.radial;
    const double sigma = along * c - o.axial * s;
    marks.push_back({period * (psi / (2 * kPi)) + sigma, along * s + o.axial * c});
  }
  return marks;
}

FeedMarkPrediction predictFeedMarks(const Cutter& cutter, double leadDeg, double tiltDeg,
                                    double fz) {
  if (cutter.type == CutterType::Flat)
    return notCovered("a flat end mill's corner is sharp (rho_f = 0): its marks are not arcs");
  if (!(std::fabs(leadDeg) > 0) || !(std::fabs(leadDeg) < 90))
    return notCovered(
        "needs a lead 0 < |lead| < 90 deg: without one the contact is at the tip, "
        "on the axis, where every tooth passes");
  if (tiltDeg != 0) return notCovered("derived for lead alone (tilt 0)");
  const std::vector<ToothRake>& rakes = cutter.teeth.toothRakes();
  if (std::any_of(rakes.begin(), rakes.end(), [](const ToothRake& r) { return !r.zero(); }))
    return notCovered(
        "a raked edge lies off the meridian plane: its points reach the contact at "
        "different spindle angles, so its marks are sheared arcs (not derived here)");
  const double lambda = degToRad(std::fabs(leadDeg));
  const ContactArc arc = contactArc(cutter, std::sin(lambda), std::cos(lambda));
  if (!arc.found) return notCovered("the contact is not on an arc of the profile: " + arc.reason);
  const double rho = arc.radius;
  if (!(fz > 0) || !(fz < 2 * rho)) {
    std::ostringstream msg;
    msg << "needs 0 < fz < 2 rho_f = " << 2 * rho << " mm";
    return notCovered(msg.str());
  }
  const CutterTeeth& teeth = cutter.teeth;
  const double period = teeth.flutes * fz;
  const double contactHeight = arc.centreS - rho * std::cos(lambda);
  const std::vector<ToothMark> marks = toothMarks(teeth, cutter.radius, contactHeight, lambda, fz);
  const SpanCheck spans = teethAtContact(cutter, arc, lambda, marks, period);
  if (!spans.reason.empty()) return notCovered(spans.reason);
  std::vector<ToothMark> leaving;
  for (int k : spans.teeth) leaving.push_back(marks[size_t(k)]);
  MarkEnvelope envelope = markEnvelope(leaving, period, rho);
  for (int& k : envelope.cuttingTeeth) k = spans.teeth[size_t(k)];
  if (!envelope.valid)
    return notCovered("two teeth's marks lie 2 rho_f or more apart: they are not arcs of rho_f");
  FeedMarkPrediction p;
  p.applicable = true;
  p.profileRadiusMm = rho;
  p.hasRunoutThreshold = teeth.flutes == 2;
  if (p.hasRunoutThreshold) p.runoutThresholdMm = runoutThreshold(rho, leadDeg, fz);
  p.cuttingTeeth = envelope.cuttingTeeth;
  p.valleyDepthsMm = envelope.valleyDepthsMm;
  p.heightMm = envelope.peakToValleyMm;
  p.heightParabolaMm = envelope.peakToValleyParabolaMm;
  const auto valleys = std::count_if(
      p.valleyDepthsMm.begin(), p.valleyDepthsMm.end(),
      [&](double depth) { return depth >= kFeedMarkHysteresis * envelope.peakToValleyMm; });
  p.spacingMm = period / double(std::max<std::ptrdiff_t>(valleys, 1));
  const int cutting = int(envelope.cuttingTeeth.size());
  const bool spansLeaveTeethOut = int(spans.teeth.size()) < teeth.flutes;
  if (!hasToothErrors(teeth) && !spansLeaveTeethOut)
    p.regime = "no runout";
  else if (cutting == 1)
    p.regime = "one tooth cuts";
  else if (cutting == teeth.flutes)
    p.regime = teeth.flutes == 2 ? "both teeth cut" : "all teeth cut";
  else
    p.regime = std::to_string(cutting) + " of " + std::to_string(teeth.flutes) + " teeth cut";
  return p;
}

}  // namespace scallop
