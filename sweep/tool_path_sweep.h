// From tool path to swept segments: drops rapids and splits moves whose axis turns
// into constant-axis pieces (CONVENTIONS.md "Tool pose").
#pragma once

#include <vector>

#include "sweep/pose.h"
#include "sweep/swept_segment.h"

namespace scallop {

struct SweepOptions {
  // Bound on how far any point of the cutter (up to the flute top) can be from where
  // the true rotating cutter puts it, mm. Sets the number of constant-axis pieces.
  double axisTolerance = 1e-4;
};

// Every cutting move becomes one or more SweptSegments. Consecutive collinear moves
// with the same axis are merged: the swept solid of their union is the same set.
std::vector<SweptSegment> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                        const SweepOptions& options = {});

}  // namespace scallop
