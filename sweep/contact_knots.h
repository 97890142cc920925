// ContactKnots: where to start a turning move's rim-contact search (rim_contact.h) on a
// vertical line, blended to second order from the contacts located at the four
// surrounding knots of a fixed lattice in the plane and how they move with the line. The start
// depends on (move, x, y) alone, so the height found from it does too, on any thread and in any
// order; knots once located are kept per thread in a small cache, so neighbouring lines share them.
#pragma once

#include <cstdint>

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "sweep/rim_contact.h"

namespace scallop {

// The lattice's default spacing h, mm: knots at (i h, j h) for integer i, j. Contacts
// move smoothly with the line, so a start blended from knots 16 um away is exact for
// quadratics (contact_knots.cpp) and Newton's method mostly converges at its first
// evaluation instead of taking four. A scene sets the spacing to about 8 of its cells
// (SceneOptions::contactKnotSpacing): knots cost about what the cells they serve save
// (16 cells: 2 % more instructions on B3).
constexpr double kContactKnotSpacing = 1.0 / 64;

// The power of two nearest to 8 cells of `cellSpacing` mm, at least 1/1024 mm, where that
// is at most 1/32 mm (cells up to ~5.6 um); 0 (no knots: starts from the middle) for
// coarser cells.
double contactKnotSpacingFor(double cellSpacing);

// A new identity for a move's knots in the caches (never 0): one for each move and
// spacing (copies of a move share it).
uint64_t newContactKnotsId();

// The start for the line through (x, y): the contacts of the knots of spacing `spacing`
// blended where all four knots have one, else (or with spacing 0) the default start
// (the middle of the move). `id` names the move and the spacing.
RimStart contactStart(uint64_t id, double spacing, const Cutter& cutter, const PoseCurve& curve,
                      double x, double y);

}  // namespace scallop
