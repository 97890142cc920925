// The teeth of a cutter grouped by their offsets, edge spans and rakes
// (tooth_geometry.h): teeth with equal offsets lie on one solid of revolution, and the
// crossing search (tooth_sweep.cpp) runs once a group, on that solid, for the F values
// of the group's teeth, keeping the points of the solid that lie on the group's span.
#pragma once

#include <vector>

#include "sweep/cutter.h"

namespace scallop {

struct ToothGroup {
  Cutter cutter;      // the teeth's solid of revolution about the cutter's axis
  Cutter envelope;    // that pushed out by the runout
  double radial = 0;  // their radial offset, mm
  double drop = 0;    // their axial offset: their tip sits `drop` below the spindle's, mm
  int flutes = 0;     // of the whole cutter
  // The F values (flutes psi_k / (2 pi), in [0, flutes)) at which one of the group's
  // teeth crosses, modulo flutes.
  std::vector<double> roots;
  bool everyInteger = false;  // roots = 0, 1, ..., flutes - 1
  double step = 0;            // the scan step, in t
  double quarterPeriod = 0;   // a quarter tooth period at equal pitch, in t
  double leaf = 0;            // the shortest interval halved where the faces agree, in t
  bool spanned = false;       // the teeth's edges cover `span` only
  EdgeSpan span;              // of the nominal profile (before the radial offset)
  ToothRake rake;             // the teeth's rake
  RakeLag lag;                // its lag, from the nominal profile's point at span.from
  // The radii from the axis between which the span's points lie (with the offset), mm.
  double spanRadiusMin = 0, spanRadiusMax = 0;

  // Whether F = f is one of the roots modulo flutes.
  bool isRoot(double f) const;
  // Whether a root lies in [lo, hi].
  bool hasRootIn(double lo, double hi) const;
  // Whether the point of the group's solid at height h above its tip and radius rho
  // from the axis lies on the teeth's span (always, without one).
  bool onSpan(double h, double rho) const;
};

// The groups of `cutter`'s teeth, deepest-reaching first (their crossings prune the
// others' search). `equalPitchStep`: the scan step (in t) of one group of every tooth
// at equal pitch, a quarter tooth period.
std::vector<ToothGroup> makeToothGroups(const Cutter& cutter, double equalPitchStep);

}  // namespace scallop
