// From tool path to swept moves: drops rapids, makes one SweptMove per cutting move
// (whatever its axis does) with the cutter of that move, and merges consecutive
// collinear moves with one axis and one cutter (CONVENTIONS.md "Tool pose", "Tools").
#pragma once

#include <cstddef>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/cutting_model.h"
#include "sweep/pose.h"
#include "sweep/swept_move.h"

namespace scallop {

// Every cutting move becomes one SweptMove whose pose curve is PoseCurve::ofMove (tip
// linear and axis slerp(from.axis, to.axis, t), or the machine's rotary motion), swept
// with cutters[move.tool]. Consecutive collinear moves with the same constant axis and
// cutter are merged: the swept solid of their union is the same set. A turn of 180
// degrees and a tool index beyond `cutters` are InputErrors naming the move.
//
// With the "teeth" cutting model each move also carries its edges (ToothSweep) with the
// spindle angle phi(s) = phi0 + 2 pi s / (flutes fz) of CuttingModel, s the tip's
// distance along the path; its envelope is then the cutter's spindleEnvelope(). A move
// without a feed per tooth (neither its own nor the model's), or whose tip follows a
// machine's curve (TCP off), is an InputError naming the move; an arc's s is its arc
// length. Arcs (Move::arc) are single moves, never merged.
std::vector<SweptMove> sweepToolPath(const std::vector<Cutter>& cutters, const ToolPath& path,
                                     const CuttingModel& cutting = {});

// The same with path.cutters when the path has its own (a multi-tool program), and
// otherwise `cutter` for every move.
std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                     const CuttingModel& cutting = {});

}  // namespace scallop
