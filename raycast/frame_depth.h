// A frame's depth (CONVENTIONS.md "Frames"): a cell holds the lowest point of the swept
// solids on the part of its line with w >= -depth, so a cut made only beyond -depth (from
// the other side of the part) leaves the cell at its stock. The cast (zmap_caster.h) finds
// the lowest point on the whole line; cells it left below -depth are computed again here.
#pragma once

#include <cstdint>

#include "base/vec3.h"
#include "raycast/grid_frame.h"
#include "raycast/swept_scene.h"
#include "raycast/zmap.h"

namespace scallop {

// For every cell of `map` (cast from `scene`, frame coordinates) below -frame.depth: the
// lowest point at or above -depth of every move that can reach its line, or its stock
// exit height, or (cut through) a point below -depth that finishFrameMap then clamps. A move whose lowest point lies below -depth cuts the cell down to -depth
// when its solid still holds the line's point at -depth: for a constant-axis move (a
// convex solid, whose trace on the line is one interval) when its highest point on the
// line, minus the lowest point of its mirror image through w = 0, is at or above -depth;
// a turning move is taken the same way (its trace is one interval unless the cutter
// leaves the line and comes back within the move). Returns the cells changed.
int64_t cutToFrameDepth(const SweptScene& scene, ZMap& map, const Box3& stock,
                        const GridFrame& frame);

}  // namespace scallop
