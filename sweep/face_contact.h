// FaceContact: where a turning bull or flat cutter's swept solid is lowest on a vertical
// line at a point of its flat bottom face, located by Newton's method over t and proven
// in closed form: the plane of the tip carried with the cutter bounds every K(t), and a
// Taylor form of it over the whole move shows that the line meets no K(t) 1e-9 mm below
// the face's lowest point. It replaces the certified search on lines that meet the face
// (B3: 98 % of the searches the rim contact leaves). Derivation in face_contact.cpp.
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "base/vec3.h"

namespace scallop {

struct FaceContact {
  bool found = false;  // false: not a face contact, or not proven; nothing below is set
  double t = 0;        // pose parameter of the contact, in [0, 1]
  double z = 0;        // mm: the lowest point of the swept solid on the line, proven to
                       // within kProofGap (certified_search.h) below
  Vec3 normal;         // -axis(t): the face's outward normal
};

// The lowest point of the swept solid on the vertical line through (x, y) where it lies
// on the bottom face of a cutter with bottomRadius() > 0, found and proven; found =
// false otherwise (the caller then goes on as before).
FaceContact locateFaceContact(const Cutter& cutter, const PoseCurve& curve, double x, double y);

}  // namespace scallop
