#include "sweep/cutter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

const char* toString(CutterType type) {
  switch (type) {
    case CutterType::Ball:
      return "ball";
    case CutterType::Flat:
      return "flat";
    case CutterType::Bull:
      return "bull";
    case CutterType::TaperBall:
      return "taper_ball";
    case CutterType::TaperBull:
      return "taper_bull";
    case CutterType::Cone:
      return "cone";
    case CutterType::Barrel:
      return "barrel";
    case CutterType::TaperBarrel:
      return "taper_barrel";
    case CutterType::Oval:
      return "oval";
    case CutterType::Lens:
      return "lens";
    case CutterType::Profile:
      return "profile";
  }
  return "?";
}

CutterType parseCutterType(const std::string& name, const std::string& field) {
  if (name == "ball") return CutterType::Ball;
  if (name == "flat") return CutterType::Flat;
  if (name == "bull") return CutterType::Bull;
  throw InputError(field, "unknown cutter type \"" + name + "\", expected ball, flat or bull");
}

namespace {

// A runout phase beyond this many degrees is a mistake, not an angle anyone means.
constexpr double kMaxPhaseDeg = 1e6;

void requireFinite(double v, const std::string& field) {
  if (!std::isfinite(v))
    throw InputError(field, "must be a finite number of mm, got " + std::to_string(v));
}

}  // namespace

Cutter Cutter::make(CutterType type, double radius, double cornerRadius, double fluteLength,
                    const std::string& fieldPrefix) {
  const std::string rField = fieldPrefix + ".radius";
  const std::string crField = fieldPrefix + ".corner_radius";
  const std::string flField = fieldPrefix + ".flute_length";
  requireFinite(radius, rField);
  if (radius <= 0) throw InputError(rField, "must be > 0 mm, got " + std::to_string(radius));
  // 1 km: beyond it no result would mean anything at micrometre resolution (and the
  // scene's tile counts would overflow); the job reader applies the same bound.
  if (radius > kMaxMagnitudeMm)
    throw InputError(rField, "must be <= 1e6 mm (1 km), got " + formatNumber(radius));

  Cutter c;
  c.type = type;
  c.radius = radius;
  switch (type) {
    case CutterType::Ball:
      c.cornerRadius = radius;
      break;
    case CutterType::Flat:
      c.cornerRadius = 0;
      break;
    case CutterType::Bull:
      requireFinite(cornerRadius, crField);
      if (cornerRadius <= 0 || cornerRadius >= radius)
        throw InputError(crField, "a bull cutter needs 0 < corner_radius < radius (" +
                                      std::to_string(radius) + " mm), got " +
                                      std::to_string(cornerRadius));
      c.cornerRadius = cornerRadius;
      break;
    default:
      throw InputError(fieldPrefix + ".type", std::string("a ") + toString(type) +
                                                  " cutter is made from its profile, not from "
                                                  "radius and corner radius");
  }
  if (std::isnan(fluteLength) || std::isinf(fluteLength))
    throw InputError(flField, "must be a finite number of mm");
  c.fluteLength = fluteLength > 0 ? fluteLength : 4 * radius;
  if (c.fluteLength > 4e6)
    throw InputError(flField, "must be <= 4e6 mm, got " + formatNumber(c.fluteLength));
  // The flute must at least contain the rounded bottom, or the solid is not the one
  // described in CONVENTIONS.md.
  if (c.fluteLength < c.cornerRadius)
    throw InputError(flField, "must be >= the corner radius (" + std::to_string(c.cornerRadius) +
                                  " mm), got " + std::to_string(c.fluteLength));
  return c;
}

CutterTeeth CutterTeeth::make(int flutes, double helixDeg, double runout, double runoutPhaseDeg,
                              double cutterRadius, const std::string& fieldPrefix) {
  if (flutes < 1 || flutes > 16)
    throw InputError(fieldPrefix + ".flutes",
                     "must be a whole number of teeth from 1 to 16, got " + std::to_string(flutes));
  if (!std::isfinite(helixDeg) || helixDeg < 0 || helixDeg > 60)
    throw InputError(fieldPrefix + ".helix_deg",
                     "must be a helix angle from 0 to 60 degrees, got " + formatNumber(helixDeg));
  // Runout is a small eccentricity; beyond R / 10 the tool is not a milling cutter any
  // more, and the spindle envelope (Cutter::spindleEnvelope) would be a poor bound.
  if (!std::isfinite(runout) || runout < 0 || runout > 0.1 * cutterRadius)
    throw InputError(fieldPrefix + ".runout_mm", "must be from 0 to radius / 10 (" +
                                                     formatNumber(0.1 * cutterRadius) +
                                                     " mm), got " + formatNumber(runout));
  if (!std::isfinite(runoutPhaseDeg) || std::abs(runoutPhaseDeg) > kMaxPhaseDeg)
    throw InputError(fieldPrefix + ".runout_phase_deg", "must be a finite angle in degrees");
  CutterTeeth teeth;
  teeth.flutes = flutes;
  teeth.helixDeg = helixDeg;
  teeth.runout = runout;
  teeth.runoutPhaseDeg = runoutPhaseDeg;
  return teeth;
}

const CutterTeeth::Table& CutterTeeth::table() const {
  static const Table kNone;
  return table_ ? *table_ : kNone;
}

CutterTeeth::Table& CutterTeeth::edit() {
  if (!table_) {
    table_ = std::make_shared<Table>();
  } else if (table_.use_count() > 1) {
    table_ = std::make_shared<Table>(*table_);
  }
  return *table_;
}

double CutterTeeth::toothAngle(int k) const {
  if (toothAnglesDeg().empty()) return 2 * kPi * k / flutes;
  return degToRad(toothAnglesDeg()[size_t(k)]);
}

double CutterTeeth::radialReach() const {
  double most = 0;
  for (const ToothOffset& o : toothOffsets()) most = std::max(most, o.radial);
  return most;
}

double CutterTeeth::axialReach() const {
  double most = 0;
  for (const ToothOffset& o : toothOffsets()) most = std::max(most, o.axial);
  return most;
}

double Cutter::edgeLength() const {
  if (!general()) return bottomRadius() + cornerRadius * kPi / 2 + (fluteLength - cornerRadius);
  return profile->arcLength();
}

double Cutter::edgeArcLength(double h, double rho) const {
  if (!general()) return profileArcLength(bottomRadius(), cornerRadius, h, rho);
  return profile->arcLengthAt(rho, h);
}

void Cutter::edgeSpanRadii(const EdgeSpan& span, double* lo, double* hi) const {
  if (general()) return profile->radiusRange(span.from, span.to, lo, hi);
  // The radius is non-decreasing along a ball, flat or bull profile.
  *lo = profileRadiusAt(bottomRadius(), cornerRadius, span.from);
  *hi = profileRadiusAt(bottomRadius(), cornerRadius, span.to);
}

void Cutter::edgeSpot(double u, double* rho, double* h) const {
  u = std::clamp(u, 0.0, edgeLength());
  if (general()) {
    const ProfilePoint p = profile->pointAt(u);
    *rho = p.rho, *h = p.s;
    return;
  }
  *rho = profileRadiusAt(bottomRadius(), cornerRadius, u);
  *h = profileHeightAt(bottomRadius(), cornerRadius, u);
}

RakeLag Cutter::rakeLag(int k) const {
  const ToothRake rake = teeth.toothRake(k);
  if (rake.zero()) return {};
  const double from = teeth.edgeSpans().empty() ? 0 : teeth.edgeSpans()[size_t(k)].from;
  double rho0, h0;
  edgeSpot(from, &rho0, &h0);
  return RakeLag(rake, rho0, h0);
}

void Cutter::checkRakes(const std::string& field) const {
  constexpr int kSamples = 4096;
  const double limit = std::sin(kPi / 3);
  for (int k = 0; k < teeth.flutes && !teeth.toothRakes().empty(); ++k) {
    const RakeLag lag = rakeLag(k);
    if (!lag.active()) continue;
    const EdgeSpan span =
        teeth.edgeSpans().empty() ? EdgeSpan{0, edgeLength()} : teeth.edgeSpans()[size_t(k)];
    for (int i = 0; i <= kSamples; ++i) {
      double rho, h;
      edgeSpot(span.from + (span.to - span.from) * i / kSamples, &rho, &h);
      const double d = lag.offset(h);
      if (std::abs(d) <= limit * rho || (rho == 0 && d == 0)) continue;
      char where[160];
      std::snprintf(where, sizeof where,
                    "tooth %d's rake face leaves the cutter's surface at height %.6g mm "
                    "(radius %.6g mm): ",
                    k, h, rho);
      throw InputError(field, std::string(where) +
                                  "the face through the edge's start must meet every point of "
                                  "its span within 60 degrees of the radial line; give the "
                                  "edge a span (edge_span) or a smaller rake (a flank's axial "
                                  "rake is its helix, helix_deg)");
    }
  }
}

Cutter Cutter::spindleEnvelope() const {
  const double out = teeth.runout + teeth.radialReach();
  if (out <= 0) return *this;
  // A point at radius rho from the cutter's axis is at most rho + runout from the
  // spindle's, and a tooth's edge at most radialReach beyond the nominal profile: the
  // profile moves out by both, its corner radius unchanged.
  Cutter env = *this;
  env.radius = radius + out;
  if (general()) {  // the same for any profile: every width grows by `out`
    env.profile = std::make_shared<const CutterProfile>(profile->widened(out));
    return env;
  }
  env.type = cornerRadius > 0 ? CutterType::Bull : CutterType::Flat;
  return env;
}

}  // namespace scallop
