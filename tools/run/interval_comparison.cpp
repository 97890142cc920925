#include "tools/run/interval_comparison.h"

#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/contact_curvature.h"
#include "analysis/pass_section.h"
#include "analysis/path_interval.h"
#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

using nlohmann::json;

namespace {

constexpr const char* kExactProcedureSource =
    "seed 000 Fig. 1 generalised: the shadow of any cutter by its support map "
    "(analysis/pass_section.h)";
constexpr const char* kEffectiveRadiusSource =
    "osculating circle at the contact, Eqs. (8), (12); seed 000 Eq. (9) at lead only "
    "(analysis/contact_curvature.h)";

json numberOrNull(bool valid, double v) {
  return valid ? json(v) : json(nullptr);
}

}  // namespace

IntervalComparison compareIntervals(const SimulatedPass& pass, double scallopMm) {
  IntervalComparison out;
  out.cutter = pass.cutter();
  out.leadDeg = pass.leadDeg();
  out.tiltDeg = pass.tiltDeg();
  out.scallopMm = scallopMm;
  out.exact = pass.halfIntervals(scallopMm);

  const Cutter& c = pass.cutter();
  // Two passes 2 L/2 apart, simulated, for every applicable L/2.
  auto simulate = [&](ProcedureComparison p) {
    if (p.applicable) p.cusp = pass.cusp(2 * p.halfIntervalMm);
    out.procedures.push_back(p);
  };
  if (c.type == CutterType::Flat || c.general()) {
    for (const ProcedureInfo& procedure : kProcedures) {
      ProcedureComparison p;
      p.name = procedure.name;
      p.source = procedure.source;
      p.reason = p.name + ": the seeds give no procedure for a " + toString(c.type) +
                 " cutter (seed 000 covers filleted, seed 001 Eq. (1) ball end mills)";
      out.procedures.push_back(p);
    }
  } else {
    ProcedureTool tool;
    tool.type = c.type == CutterType::Ball ? ProcedureToolType::Ball : ProcedureToolType::Bull;
    tool.radiusMm = c.radius;
    tool.cornerRadiusMm = c.type == CutterType::Ball ? 0 : c.cornerRadius;
    for (const NamedProcedureResult& r : halfIntervalProcedures(tool, pass.leadDeg(), scallopMm)) {
      ProcedureComparison p;
      p.name = r.name;
      p.source = r.source;
      p.applicable = r.result.applicable;
      p.reason = r.result.reason;
      // A ball's sphere looks the same in every posture; a torus does not, and the
      // filleted procedures of seed 000 model the inclination along the feed only.
      if (p.applicable && c.type == CutterType::Bull && pass.tiltDeg() != 0) {
        p.applicable = false;
        p.reason = r.name + ": seed 000 models inclination along the feed only; tilt = " +
                   fmt::format("{:g}", pass.tiltDeg()) + " deg is outside it";
      }
      if (p.applicable) p.halfIntervalMm = r.result.value;
      simulate(p);
    }
  }
  // The procedures for every cutter, lead and tilt.
  const ProcedureResult exact = halfIntervalExact(c, pass.leadDeg(), pass.tiltDeg(), scallopMm);
  simulate({"exact", kExactProcedureSource, exact.applicable, exact.reason, exact.value, {}});
  const ProcedureResult osculating =
      halfIntervalEffectiveRadius(c, pass.leadDeg(), pass.tiltDeg(), scallopMm);
  simulate({"effective_radius",
            kEffectiveRadiusSource,
            osculating.applicable,
            osculating.reason,
            osculating.value,
            {}});
  return out;
}

json toolJson(const Cutter& cutter) {
  json t = {{"type", toString(cutter.type)}, {"radius", cutter.radius}};
  if (cutter.type == CutterType::Bull) t["corner_radius"] = cutter.cornerRadius;
  return t;
}

json toJson(const IntervalComparison& c) {
  json doc;
  doc["tool"] = toolJson(c.cutter);
  doc["lead_deg"] = c.leadDeg;
  doc["tilt_deg"] = c.tiltDeg;
  doc["scallop"] = c.scallopMm;
  doc["simulated_half_interval"] = c.exact.halfIntervalMm();
  doc["simulated_half_interval_plus"] = c.exact.plusMm;
  doc["simulated_half_interval_minus"] = c.exact.minusMm;
  json procs = json::array();
  for (const ProcedureComparison& p : c.procedures) {
    const bool simulated = p.applicable && p.cusp.covered;
    procs.push_back({{"name", p.name},
                     {"source", p.source},
                     {"applicable", p.applicable},
                     {"reason", p.reason},
                     {"half_interval", numberOrNull(p.applicable, p.halfIntervalMm)},
                     {"simulated_scallop", numberOrNull(simulated, p.cusp.heightMm)},
                     {"scallop_error", numberOrNull(simulated, p.cusp.heightMm - c.scallopMm)},
                     {"half_interval_error",
                      numberOrNull(p.applicable, p.halfIntervalMm - c.exact.halfIntervalMm())}});
  }
  doc["procedures"] = procs;
  if (c.feedPerToothMm > 0) {
    const FeedMarkPrediction& f = c.feedMarks;
    json marks = {{"feed_per_tooth", c.feedPerToothMm},
                  {"flutes", c.cutter.teeth.flutes},
                  {"runout", c.cutter.teeth.runout},
                  {"applicable", f.applicable},
                  {"reason", f.reason},
                  {"formula",
                   "h_f = rho_f - sqrt(rho_f^2 - s^2 / 4) ~ s^2 / (8 rho_f), s the "
                   "spacing; rho_f = R (ball) or r (bull)"},
                  {"source", "docs/teeth.md"}};
    marks["profile_radius"] = numberOrNull(f.applicable, f.profileRadiusMm);
    marks["spacing"] = numberOrNull(f.applicable, f.spacingMm);
    marks["height"] = numberOrNull(f.applicable, f.heightMm);
    marks["height_parabola"] = numberOrNull(f.applicable, f.heightParabolaMm);
    marks["regime"] = f.regime;
    marks["runout_threshold"] =
        numberOrNull(f.applicable && f.hasRunoutThreshold, f.runoutThresholdMm);
    doc["feed_marks"] = marks;
  }
  doc["units"] = {{"length", "mm"}, {"angle", "deg"}};
  return doc;
}

void checkAngleOption(const char* option, double deg) {
  if (!std::isfinite(deg) || std::fabs(deg) >= 90)
    throw InputError(
        option, "must be an angle in degrees with |angle| < 90, got " + fmt::format("{:g}", deg));
}

Cutter cutterFromOptions(const std::string& tool, double radius, double cornerRadius,
                         bool cornerGiven, const IntervalFieldNames& names) {
  const CutterType type = parseCutterType(tool, names.tool);
  if (!(radius > 0) || !(radius <= kMaxMagnitudeMm))
    throw InputError(names.radius,
                     "must be a length in (0, 1e6] mm, got " + fmt::format("{:g}", radius));
  if (type != CutterType::Bull) {
    if (cornerGiven)
      throw InputError(names.cornerRadius,
                       std::string("only a bull cutter has a corner radius; a ") + toString(type) +
                           " cutter's is fixed");
    return Cutter::make(type, radius, 0, 0, "tool");
  }
  if (!cornerGiven) throw InputError(names.cornerRadius, "is required for a bull cutter");
  if (!std::isfinite(cornerRadius) || cornerRadius <= 0 || cornerRadius >= radius)
    throw InputError(names.cornerRadius,
                     "must satisfy 0 < corner radius < radius = " + fmt::format("{:g}", radius) +
                         " mm for a bull cutter, got " + fmt::format("{:g}", cornerRadius) +
                         " (corner radius = radius is " + names.tool + " ball)");
  return Cutter::make(type, radius, cornerRadius, 0, "tool");
}

IntervalComparison compareIntervals(const IntervalRequest& request,
                                    const IntervalFieldNames& names) {
  const Cutter cutter = cutterFromOptions(request.tool, request.radiusMm, request.cornerRadiusMm,
                                          request.cornerGiven, names);
  checkAngleOption(names.lead, request.leadDeg);
  checkAngleOption(names.tilt, request.tiltDeg);
  if (!std::isfinite(request.scallopMm) || request.scallopMm <= 0)
    throw InputError(names.scallop,
                     "must be a height > 0 mm, got " + fmt::format("{:g}", request.scallopMm));
  if (request.feedPerToothGiven &&
      (!(request.feedPerToothMm > 0) || !(request.feedPerToothMm <= kMaxMagnitudeMm)))
    throw InputError(names.feedPerTooth, "must be a feed per tooth > 0 mm (at most 1e6), got " +
                                             fmt::format("{:g}", request.feedPerToothMm));
  CutterTeeth teeth;
  try {
    teeth = CutterTeeth::make(request.flutes, 0, request.runoutMm, 0, cutter.radius, "tool");
  } catch (const InputError& e) {
    const bool flutes = e.where() == "tool.flutes";
    throw InputError(flutes ? names.flutes : names.runout, e.reason());
  }
  const SimulatedPass pass(cutter, request.leadDeg, request.tiltDeg);
  IntervalComparison comparison = compareIntervals(pass, request.scallopMm);
  if (!comparison.exact.reachable) throw InputError(names.scallop, comparison.exact.reason);
  comparison.cutter.teeth = teeth;
  if (request.feedPerToothGiven) {
    comparison.feedPerToothMm = request.feedPerToothMm;
    comparison.feedMarks = predictFeedMarks(comparison.cutter, request.leadDeg, request.tiltDeg,
                                            request.feedPerToothMm);
  }
  return comparison;
}

}  // namespace scallop
