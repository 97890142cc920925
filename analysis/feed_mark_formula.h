// Feed marks of a cutter with teeth on a plane, in closed form (docs/teeth.md).
//
// Along the centre line of a straight pass whose axis leans by the lead lambda along
// the feed (0 < |lambda| < 90 deg, no tilt), each tooth leaves, at its pass over the
// contact point, the meridian section of the cutter there: a circle of the feed-
// direction profile radius rho_f (R for a ball, the corner radius r for a bull, whose
// contact with a plane is on the corner when the tool leans). Consecutive teeth are
// fz apart, so the marks are circular arcs of chord fz and height
//     h_f = rho_f - sqrt(rho_f^2 - fz^2 / 4)  ~  fz^2 / (8 rho_f).
// Not covered: a flat end mill (a sharp corner, rho_f = 0), no lead (the contact is at
// the tip, on the axis, where every tooth passes), a tilt (not derived here).
//
// Runout rho with 2 flutes (phase 0 or 180 deg, no helix: one tooth pushed out towards
// the contact): the tool is shifted by +-rho along (cos lambda, 0, -sin lambda) when a
// tooth is at the contact, so one tooth cuts dz = 2 rho sin(lambda) lower and the two
// teeth's marks are shifted by sigma = 2 rho cos(lambda) along the feed. With
// parabolic arcs (curvature 1 / rho_f) the higher tooth still cuts iff
//     dz < (fz - sigma)(fz + sigma) / (2 rho_f),
// whose equality gives the threshold
//     rho* = (-rho_f sin(lambda) + sqrt(rho_f^2 sin^2(lambda) + fz^2 cos^2(lambda)))
//            / (2 cos^2(lambda))  ~  fz^2 / (4 rho_f sin(lambda)).
// Above it the lower tooth cuts alone: arcs of chord 2 fz. Below it both cut; the
// cusps between a lower-tooth arc at 0 and the higher one at d = fz -+ sigma (height
// dz) lie at x = (2 rho_f dz + d^2) / (2 d) from the lower arc's bottom, at height
// x^2 / (2 rho_f); the marks' peak-to-valley is the higher of the two cusps.
#pragma once

#include <string>

#include "sweep/cutter.h"

namespace scallop {

// h = rho - sqrt(rho^2 - chord^2 / 4): a circular arc's height over its chord, mm.
double circularMarkHeight(double profileRadiusMm, double chordMm);

// rho*, mm, for the feed-direction profile radius rho_f, lead (deg) and fz (mm).
double runoutThreshold(double profileRadiusMm, double leadDeg, double feedPerToothMm);

struct FeedMarkPrediction {
  bool applicable = false;
  std::string reason;               // why not; empty when applicable
  double profileRadiusMm = 0;       // rho_f
  double spacingMm = 0;             // between marks: fz, or 2 fz when one tooth cuts alone
  double heightMm = 0;              // peak-to-valley: the circle's (the parabola's with runout
                                    // below the threshold, where both teeth cut)
  double heightParabolaMm = 0;      // spacing^2 / (8 rho_f), or the cusp of the parabolic arcs
  bool hasRunoutThreshold = false;  // 2 flutes
  double runoutThresholdMm = 0;     // rho*
  std::string regime;               // "no runout", "both teeth cut", "one tooth cuts"
};

// The feed marks `cutter` (its teeth: flutes, helix, runout) leaves along the centre
// line of a pass at `leadDeg`, `tiltDeg` with fz = `feedPerToothMm` (> 0).
FeedMarkPrediction predictFeedMarks(const Cutter& cutter, double leadDeg, double tiltDeg,
                                    double feedPerToothMm);

}  // namespace scallop
