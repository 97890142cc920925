// deviation.png: the machined surface's signed deviation from the design, for people.
//
// Diverging colour map symmetric about 0: blue where material is left (machined above
// design, under-cut), white at 0, red where the cutter went below the design
// (over-cut; deeper than the gouge tolerance: a gouge). The colour range is +-L with
// L the 99th percentile of |deviation| rounded up to 1, 2 or 5 x 10^k, so that a few
// extreme cells (a cliff, the floor outside the part) do not wash the picture out;
// cells beyond it take the end colours. Grey: no design surface there. Each gouge's
// deepest cell is ringed in black. Legend in um (mm when L >= 0.5 mm), north up.
// Large maps are reduced by an integer factor keeping, per block, the deepest
// over-cut if there is one (so gouges stay visible), else the largest deviation.
#pragma once

#include <string>

#include "analysis/design_deviation.h"

namespace scallop {

// Writes atomically; returns L, the colour range's half width, mm.
double writeDeviationPng(const DesignComparison& comparison, const std::string& path,
                         const std::string& title, int maxPixels = 1600);

}  // namespace scallop
