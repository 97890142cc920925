#include "sweep/cutter.h"

#include <cmath>
#include <sstream>
#include <string>

#include "sweep/input_error.h"

namespace scallop {

const char* toString(CutterType type) {
  switch (type) {
    case CutterType::Ball:
      return "ball";
    case CutterType::Flat:
      return "flat";
    case CutterType::Bull:
      return "bull";
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

void requireFinite(double v, const std::string& field) {
  if (!std::isfinite(v))
    throw InputError(field, "must be a finite number of mm, got " + std::to_string(v));
}

std::string fmtLength(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
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
  if (radius > 1e6) throw InputError(rField, "must be <= 1e6 mm (1 km), got " + fmtLength(radius));

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
  }
  if (std::isnan(fluteLength) || std::isinf(fluteLength))
    throw InputError(flField, "must be a finite number of mm");
  c.fluteLength = fluteLength > 0 ? fluteLength : 4 * radius;
  if (c.fluteLength > 4e6)
    throw InputError(flField, "must be <= 4e6 mm, got " + fmtLength(c.fluteLength));
  // The flute must at least contain the rounded bottom, or the solid is not the one
  // described in CONVENTIONS.md.
  if (c.fluteLength < c.cornerRadius)
    throw InputError(flField, "must be >= the corner radius (" + std::to_string(c.cornerRadius) +
                                  " mm), got " + std::to_string(c.fluteLength));
  return c;
}

}  // namespace scallop
