// From tool path to swept moves: drops rapids, makes one SweptMove per cutting move
// (whatever its axis does), and merges consecutive collinear moves with one axis
// (CONVENTIONS.md "Tool pose").
#pragma once

#include <vector>

#include "sweep/pose.h"
#include "sweep/swept_move.h"

namespace scallop {

// Every cutting move becomes one SweptMove whose pose curve is tip linear, axis
// slerp(from.axis, to.axis, t). Consecutive collinear moves with the same constant
// axis are merged: the swept solid of their union is the same set. A turn of 180
// degrees is an InputError naming the move.
std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path);

}  // namespace scallop
