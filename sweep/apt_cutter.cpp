#include "sweep/apt_cutter.h"

#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"
#include "sweep/cutter_shapes.h"
#include "sweep/profile_chain.h"

namespace scallop {

namespace {

void requireGiven(double given, double expected, const std::string& field, const char* what) {
  if (std::fabs(given - expected) <= kAptTangencyToleranceMm) return;
  throw InputError(field, std::string("is ") + formatNumber(given) + " mm, but the corner " + what +
                              " is " + formatNumber(expected) +
                              " mm (the corner must be tangent to both lines within 1e-6 mm)");
}

}  // namespace

std::vector<ProfileSegment> aptCutterChain(const AptCutterValues& v, const std::string& field) {
  requirePositiveLength(v.d, field + ".d");
  requireWithin(v.r, 0, kMaxMagnitudeMm, false, false, field + ".r", "mm");
  requireWithin(v.a, 0, 90, false, true, field + ".a", "degrees (alpha, the bottom line's angle)");
  requireWithin(v.b, -90, 90, true, true, field + ".b", "degrees (beta, the side line's angle)");
  if (!(v.a + v.b < 90))
    throw InputError(field + ".b",
                     "a + b must be < 90 degrees (the side line must turn up from "
                     "the bottom line), got " +
                         formatNumber(v.a + v.b));
  requireWithin(v.e, -kMaxMagnitudeMm, kMaxMagnitudeMm, false, false, field + ".e", "mm");
  requireWithin(v.f, -kMaxMagnitudeMm, kMaxMagnitudeMm, false, false, field + ".f", "mm");
  requirePositiveLength(v.h, field + ".h");
  const double a = v.a * kRadPerDeg, b = v.b * kRadPerDeg;
  // The lines meet at P; each has a unit direction u (up the profile) and an inward
  // normal n (towards the solid).
  const ProfilePoint P{v.d / 2, v.d / 2 * std::tan(a)};
  const double n1r = -std::sin(a), n1s = std::cos(a);  // bottom: through the tip
  const double n2r = -std::cos(b), n2s = std::sin(b);  // side: through P
  ProfilePoint low = P, high = P;                      // the corner's ends on each line
  ProfilePoint centre = P;
  if (v.r > 0) {
    // n1 . C = r and n2 . (C - P) = r; the determinant is cos(a + b) > 0.
    const double q = v.r + n2r * P.rho + n2s * P.s;
    const double det = n1r * n2s - n1s * n2r;
    centre = {(v.r * n2s - n1s * q) / det, (n1r * q - n2r * v.r) / det};
    requireGiven(v.e, centre.rho, field + ".e", "centre's distance from the axis");
    requireGiven(v.f, centre.s, field + ".f", "centre's height above the tip");
    low = {centre.rho - v.r * n1r, centre.s - v.r * n1s};
    high = {centre.rho - v.r * n2r, centre.s - v.r * n2s};
    // The tangent point on the bottom line lies at low . u1 from the tip; a negative
    // value puts the corner across the axis. On the axis it is exactly the tip.
    const double along = low.rho * std::cos(a) + low.s * std::sin(a);
    if (along < -kAptTangencyToleranceMm)
      throw InputError(field + ".e",
                       "puts the corner across the axis (its tangent point on the "
                       "bottom line is " +
                           formatNumber(-along) +
                           " mm beyond the tip); the corner must fit within d");
    if (along <= kAptTangencyToleranceMm) low = {0, 0};
  } else {
    const bool atOrigin =
        std::fabs(v.e) <= kAptTangencyToleranceMm && std::fabs(v.f) <= kAptTangencyToleranceMm;
    if (!atOrigin) {
      requireGiven(v.e, P.rho, field + ".e",
                   "point's distance from the axis (r = 0; or e = f = 0)");
      requireGiven(v.f, P.s, field + ".f", "point's height above the tip (r = 0; or e = f = 0)");
    }
  }
  if (!(v.h >= high.s))
    throw InputError(field + ".h", "must be above the corner's upper end, " + formatNumber(high.s) +
                                       " mm, got " + formatNumber(v.h));
  std::vector<ProfileSegment> chain;
  appendLine(chain, {0, 0}, low);
  if (v.r > 0) appendArc(chain, low, high, v.r, centre);
  appendLine(chain, high, {high.rho + (v.h - high.s) * std::tan(b), v.h});
  return chain;
}

Cutter aptCutter(const AptCutterValues& v, const std::string& field) {
  std::vector<ProfileSegment> chain = aptCutterChain(v, field);
  if (v.a == 0 && v.b == 0) {
    // An end mill: its own type and kernel, so its heights are today's bit for bit.
    const double R = v.d / 2;
    const CutterType type = v.r == 0                                        ? CutterType::Flat
                            : std::fabs(v.r - R) <= kAptTangencyToleranceMm ? CutterType::Ball
                                                                            : CutterType::Bull;
    return Cutter::make(type, R, v.r, v.h, field);
  }
  return cutterOfChain(CutterType::Profile, std::move(chain), field);
}

}  // namespace scallop
