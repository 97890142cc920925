// The named cutter shapes of CONVENTIONS.md "Cutter shapes", built from the parameters
// tool catalogues give: each *Chain function checks its parameters and returns the
// profile chain (sweep/cutter_profile.h) from the tip up, arc centres filled in;
// cutterOfChain turns a chain into a Cutter. Lengths in mm, angles in degrees. Every
// error is an InputError naming `field` + "." + the job key ("tool.taper_deg") and the
// range expected.
#pragma once

#include <string>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/cutter_profile.h"

namespace scallop {

// A ball tip of radius `tipRadius` on a cone of half-angle `taperDeg` (per side),
// tangent at (r cos b, r (1 - sin b)); the flank ends at `fluteLength`, or, when that
// is 0, where its diameter is `fluteDiameter`.
struct TaperBallShape {
  double tipRadius = 0, taperDeg = 0, fluteLength = 0, fluteDiameter = 0;
};
// A tapered corner-radius mill: `tipDiameter` where the flat bottom and the flank
// (both extended) meet, as a sharp tapered end mill's, rounded by `cornerRadius`
// tangent to both; flank and flute top as TaperBallShape.
struct TaperBullShape {
  double tipDiameter = 0, cornerRadius = 0, taperDeg = 0, fluteLength = 0, fluteDiameter = 0;
};
// V-bits, chamfer mills, drill points: a cone of included angle `angleDeg` from a flat
// tip of `tipDiameter` (0: a sharp point) out to `diameter`, then the cylinder of that
// diameter up to `fluteLength`.
struct ConeShape {
  double angleDeg = 0, tipDiameter = 0, diameter = 0, fluteLength = 0;
};
// Barrel: a side arc of `formRadius` whose widest point, of `diameter`, is at
// `equatorHeight` above the tip (<= 0: half the flute length, a symmetric barrel),
// joined to a flat bottom by a corner arc of `tipRadius` (0: a sharp edge).
struct BarrelShape {
  double diameter = 0, formRadius = 0, tipRadius = 0, equatorHeight = 0, fluteLength = 0;
};
// Taper barrel (conical barrel): a ball tip of `tipRadius` and a side arc of
// `formRadius` tangent to it, whose tangent makes `taperDeg` with the axis where its
// diameter is `referenceDiameter`; the side arc runs up to `fluteLength`.
struct TaperBarrelShape {
  double tipRadius = 0, formRadius = 0, taperDeg = 0, referenceDiameter = 0, fluteLength = 0;
};
// Oval: a ball tip of `tipRadius` and a side arc of `formRadius` tangent to it whose
// widest point has `diameter`; the side arc runs up to `fluteLength`.
struct OvalShape {
  double diameter = 0, formRadius = 0, tipRadius = 0, fluteLength = 0;
};
// Lens: a tip arc of `formRadius` centred on the axis, a corner arc of `cornerRadius`
// (0: a sharp edge) and the cylinder of `diameter` up to `fluteLength`.
struct LensShape {
  double diameter = 0, formRadius = 0, cornerRadius = 0, fluteLength = 0;
};

std::vector<ProfileSegment> taperBallChain(const TaperBallShape& shape, const std::string& field);
std::vector<ProfileSegment> taperBullChain(const TaperBullShape& shape, const std::string& field);
std::vector<ProfileSegment> coneChain(const ConeShape& shape, const std::string& field);
std::vector<ProfileSegment> barrelChain(const BarrelShape& shape, const std::string& field);
std::vector<ProfileSegment> taperBarrelChain(const TaperBarrelShape& shape,
                                             const std::string& field);
std::vector<ProfileSegment> ovalChain(const OvalShape& shape, const std::string& field);
std::vector<ProfileSegment> lensChain(const LensShape& shape, const std::string& field);

// The cutter of `type` (any but ball, flat, bull) whose profile is `chain`, checked by
// CutterProfile::make (errors name `field`.segments[i]): radius its largest radius,
// fluteLength its L, cornerRadius 0.
Cutter cutterOfChain(CutterType type, std::vector<ProfileSegment> chain, const std::string& field);

// The same solid: type, radius, corner radius, flute length and profile chain equal
// (the teeth are not compared).
bool sameShape(const Cutter& a, const Cutter& b);

}  // namespace scallop
