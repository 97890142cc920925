// Cutter: the milling tool as a solid of revolution (CONVENTIONS.md "Cutters").
//
// In the tool frame (tip at the origin, axis a, s = height along a) every cutter is
//     K = ( Cyl(Rb; s in [r, L]) (+) Ball(r) )  intersected with  { s <= L }
// where Rb = R - r is the radius of the flat bottom, r the corner radius and L the
// flute length. ball: Rb = 0, r = R.  flat: r = 0.  bull: 0 < r < R.
// K is convex; this is what makes the swept-solid heights exact and cheap.
#pragma once

#include <string>

namespace scallop {

enum class CutterType { Ball, Flat, Bull };

const char* toString(CutterType type);
// Parses "ball" | "flat" | "bull"; throws InputError naming `field` otherwise.
CutterType parseCutterType(const std::string& name, const std::string& field = "tool.type");

struct Cutter {
  CutterType type = CutterType::Ball;
  double radius = 0;        // R, mm
  double cornerRadius = 0;  // r, mm (R for ball, 0 for flat)
  double fluteLength = 0;   // L, mm: height of the cylindrical part's top above the tip

  // Validates and builds a cutter. `cornerRadius` is only read for bull cutters;
  // `fluteLength` <= 0 means the default 4 R. Throws InputError naming
  // `fieldPrefix` + ".radius" / ".corner_radius" / ".flute_length".
  static Cutter make(CutterType type, double radius, double cornerRadius = 0,
                     double fluteLength = 0, const std::string& fieldPrefix = "tool");

  double bottomRadius() const { return radius - cornerRadius; }  // Rb, mm
};

}  // namespace scallop
