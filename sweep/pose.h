// Pose and Move: where the cutter is (APT CL convention, CONVENTIONS.md "Tool pose").
#pragma once

#include <vector>

#include "sweep/vec3.h"

namespace scallop {

struct Pose {
  Vec3 tip;   // centre of the cutter's bottom on its axis, mm
  Vec3 axis;  // unit vector from the tip towards the shank
};

// A linear move: the tip goes straight from `from.tip` to `to.tip`; the axis is
// interpolated (slerp) when the two axes differ. Rapids never touch the stock and
// are not simulated.
struct Move {
  Pose from;
  Pose to;
  bool rapid = false;
};

struct ToolPath {
  std::vector<Move> moves;
  size_t cuttingMoves() const;
};

}  // namespace scallop
