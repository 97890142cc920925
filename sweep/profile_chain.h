// The pieces every cutter-shape builder (sweep/cutter_shapes.h, sweep/apt_cutter.h)
// assembles a CutterProfile chain from: line and arc segments between known points,
// and the checks of the parameters they come from, whose InputErrors name the job key.
#pragma once

#include <string>
#include <vector>

#include "sweep/cutter_profile.h"

namespace scallop {

// Appends the straight segment a -> b, unless it is shorter than 1e-12 mm (a chain
// has no empty pieces).
void appendLine(std::vector<ProfileSegment>& chain, ProfilePoint a, ProfilePoint b);
// Appends the arc a -> b of `radius` about `centre` (the shorter arc, bulging away from
// the solid), unless a and b coincide within 1e-12 mm.
void appendArc(std::vector<ProfileSegment>& chain, ProfilePoint a, ProfilePoint b, double radius,
               ProfilePoint centre);

// The parameter checks: a finite value within [lo, hi] (or the open bounds), else an
// InputError naming `field` that says the range and the unit.
void requireWithin(double value, double lo, double hi, bool openLo, bool openHi,
                   const std::string& field, const char* unit);
// A length > 0 mm (and <= kMaxMagnitudeMm).
void requirePositiveLength(double value, const std::string& field);
// An angle in degrees with |angle| < 90 (a lead or a tilt).
void requireAngle(double deg, const std::string& field);

}  // namespace scallop
