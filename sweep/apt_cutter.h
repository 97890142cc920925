// APT's 7-parameter cutter CUTTER/d,r,e,f,a,b,h as CONVENTIONS.md "Cutter shapes" fixes
// it (mm and degrees): a bottom line from the tip at `a` (alpha) from the horizontal, a
// side line at `b` (beta) from the axis, meeting (both extended) at diameter `d`, a
// corner of radius `r` tangent to both with its centre at (e, f), the height `h`.
#pragma once

#include <string>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/cutter_profile.h"

namespace scallop {

struct AptCutterValues {
  double d = 0, r = 0, e = 0, f = 0, a = 0, b = 0, h = 0;
};

// How far (mm) the given corner centre (e, f) may be from the one tangent to both
// lines.
constexpr double kAptTangencyToleranceMm = 1e-6;

// The profile chain of the 7 values. Checks d > 0, r >= 0, 0 <= a < 90, -90 < b < 90,
// a + b < 90, (e, f) within kAptTangencyToleranceMm of the corner centre tangent to
// both lines (with r = 0: (0, 0) or the corner point), the corner not crossing the axis
// and h above the corner; every InputError names `field` + "." + the letter ("tool.e").
std::vector<ProfileSegment> aptCutterChain(const AptCutterValues& v, const std::string& field);

// The cutter: with a = b = 0 a ball (r = d/2), flat (r = 0) or bull, bit for bit the
// cutter of those types; any other a `profile` cutter of aptCutterChain.
Cutter aptCutter(const AptCutterValues& v, const std::string& field);

}  // namespace scallop
