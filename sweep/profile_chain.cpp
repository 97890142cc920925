#include "sweep/profile_chain.h"

#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

namespace {

constexpr double kEmptySegmentMm = 1e-12;

}  // namespace

void appendLine(std::vector<ProfileSegment>& chain, ProfilePoint a, ProfilePoint b) {
  if (std::hypot(b.rho - a.rho, b.s - a.s) <= kEmptySegmentMm) return;
  ProfileSegment seg;
  seg.rho0 = a.rho, seg.s0 = a.s, seg.rho1 = b.rho, seg.s1 = b.s;
  chain.push_back(seg);
}

void appendArc(std::vector<ProfileSegment>& chain, ProfilePoint a, ProfilePoint b, double radius,
               ProfilePoint centre) {
  if (std::hypot(b.rho - a.rho, b.s - a.s) <= kEmptySegmentMm) return;
  ProfileSegment seg;
  seg.rho0 = a.rho, seg.s0 = a.s, seg.rho1 = b.rho, seg.s1 = b.s;
  seg.arcRadius = radius;
  seg.centreRho = centre.rho, seg.centreS = centre.s;
  chain.push_back(seg);
}

void requireWithin(double value, double lo, double hi, bool openLo, bool openHi,
                   const std::string& field, const char* unit) {
  const bool above = openLo ? value > lo : value >= lo;
  const bool below = openHi ? value < hi : value <= hi;
  if (std::isfinite(value) && above && below) return;
  throw InputError(field, std::string("must be in ") + (openLo ? "(" : "[") + formatNumber(lo) +
                              ", " + formatNumber(hi) + (openHi ? ")" : "]") + " " + unit +
                              ", got " + formatNumber(value));
}

void requirePositiveLength(double value, const std::string& field) {
  requireWithin(value, 0, kMaxMagnitudeMm, true, false, field, "mm");
}

void requireAngle(double deg, const std::string& field) {
  if (!std::isfinite(deg) || std::fabs(deg) >= 90)
    throw InputError(field,
                     "must be an angle in degrees with |angle| < 90, got " + formatNumber(deg));
}

}  // namespace scallop
