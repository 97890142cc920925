// SimulatedInterval: the path interval measured on the simulated surface, the truth
// the procedures of analysis/path_interval.h are checked against.
//
// One straight pass along +x with a fixed axis (leadTiltAxis: lead towards +x = f,
// tilt towards +y = c) is swept and put in a SweptScene; the floor is the plane
// through the cutter's lowest point (the depth rule of CONVENTIONS.md), z = 0 here,
// and every height below is measured from it. Far from the pass's ends the surface
// left at x = 0 is the cutter's shadow along the feed, the same for every x.
//
// Cross-feed distances are measured from the pass's centre line: the y of the tool
// centre point C = tip + r a (r the corner radius), the centre of the torus's spine
// circle in seed 000 Fig. 3 and of the ball in seed 001 Fig. 1 (the tip for a flat
// cutter). With lead only the profile is symmetric about it; a tilt makes the two
// sides differ, so both are reported: `plus` on the +c side, `minus` on the -c side.
//
// Exactness ("sub-cell"): a z-map column (castZMap on a one-cell-wide grid) only
// brackets a root between two cell centres; the root is then refined by bisection on
// SweptScene::lowestHeight, the exact double-precision height at any (x, y), so the
// answer does not depend on the grid spacing. The profile is the lower boundary of a
// convex solid on a line, hence convex: monotone on each side of its minimum (one
// root per side) and, for two passes, min(rising, falling) is unimodal between them.
#pragma once

#include <memory>
#include <string>

#include "analysis/scallop_profile.h"
#include "sweep/cutter.h"
#include "base/vec3.h"

namespace scallop {

class SweptScene;

struct SimulatedIntervalOptions {
  double bracketSpacingMm = 0;  // z-map samples that bracket the roots; <= 0: R / 256
  double toleranceMm = 1e-12;   // bisection / golden-section width on y, mm
};

// Where a single pass's profile rises h above the floor, on each side of the centre.
struct SideIntervals {
  bool reachable = false;  // false: h is beyond the cutter on at least one side
  std::string reason;      // why not reachable; empty otherwise
  // Signed distances from the centre line (positive outwards; a tilt can put a root
  // on the other side of the centre line, then it is negative).
  double plusMm = 0;   // +c side: where the height reaches h, y = +plus
  double minusMm = 0;  // -c side: y = -minus
  // Half the step-over at which two passes leave a cusp of exactly h: the +c side of
  // one pass meets the -c side of the next, so the step-over is plus + minus.
  double halfIntervalMm() const { return 0.5 * (plusMm + minusMm); }
};

// The cusp left between two passes `stepOverMm` apart (the second on the +c side).
struct SimulatedCusp {
  bool covered = false;   // false: the passes do not overlap, a strip stays uncut
  double heightMm = 0;    // highest point between the passes above the floor
  double positionMm = 0;  // its cross-feed distance from the first pass's centre line
};

class SimulatedPass {
 public:
  // Throws InputError for |lead| or |tilt| >= 90 deg ("lead_deg" / "tilt_deg").
  SimulatedPass(const Cutter& cutter, double leadDeg, double tiltDeg,
                const SimulatedIntervalOptions& options = {});
  ~SimulatedPass();
  SimulatedPass(const SimulatedPass&) = delete;
  SimulatedPass& operator=(const SimulatedPass&) = delete;

  const Cutter& cutter() const { return cutter_; }
  double leadDeg() const { return leadDeg_; }
  double tiltDeg() const { return tiltDeg_; }

  // Exact height above the floor at cross-feed distance y from the centre line, mm;
  // `ceilingMm()` where the pass does not reach (beyond its shadow).
  double heightAboveFloor(double y) const;
  double ceilingMm() const { return ceiling_; }
  // The cross-feed extent of the pass's shadow: y in [-reachMinus, reachPlus], mm.
  double reachPlusMm() const { return reachPlus_; }
  double reachMinusMm() const { return reachMinus_; }
  // Where the profile is lowest (its floor contact), from the centre line, mm.
  double floorPositionMm() const { return floorY_; }
  // The pass itself, for independent checks: the tip runs from tip - halfLength x to
  // tip + halfLength x with this axis; the floor is z = 0; the centre line is at
  // y = centreY.
  const Vec3& tip() const { return tip_; }
  const Vec3& axis() const { return axis_; }
  double halfLengthMm() const { return halfLength_; }
  double centreY() const { return centreY_; }

  // The cross-feed profile as a z-map column: positions from the centre line, heights
  // above the floor, cell centres spacing apart from `fromMm` to (at least) `toMm`.
  ScallopProfile profile(double fromMm, double toMm, double spacingMm) const;

  // Exact distances at which the profile rises `scallopHeightMm` above the floor.
  SideIntervals halfIntervals(double scallopHeightMm) const;

  // Two passes `stepOverMm` apart: the cusp height between them (new scene, exact).
  SimulatedCusp cusp(double stepOverMm) const;

 private:
  Cutter cutter_;
  double leadDeg_, tiltDeg_;
  SimulatedIntervalOptions options_;
  Vec3 axis_, tip_;  // tip at x = 0 of the pass along y = 0, floor at z = 0
  double centreY_ = 0, ceiling_ = 0, reachPlus_ = 0, reachMinus_ = 0, floorY_ = 0;
  double halfLength_ = 0;  // the pass runs from x = -halfLength to +halfLength
  std::unique_ptr<SweptScene> scene_;

  double bracketSpacing() const;
  // One side's root; `sign` +1 for +c, -1 for -c. Returns false at the flank.
  bool sideRoot(double h, int sign, double* y, double* edgeHeight) const;
};

}  // namespace scallop
