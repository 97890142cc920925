// Areal surface metrology of a z-map: least-squares plane levelling and the
// ISO 25178-2 height parameters Sa, Sq, Ssk, Sku, Sp, Sv, Sz over a region of cells.
//
// Definitions (heights z(x, y) measured from the reference surface, over the n
// cells of the region, each cell one sample):
//   Sa = mean |z|,  Sq = sqrt(mean z^2),  Ssk = mean z^3 / Sq^3,
//   Sku = mean z^4 / Sq^4  (the plain kurtosis: 3 for a Gaussian surface; Gwyddion
//   shows the *excess* kurtosis, Sku - 3),
//   Sp = max z,  Sv = -min z (a positive depth),  Sz = Sp + Sv.
// The reference surface is the least-squares plane z = a x + b y + c of the region
// (Levelling::kPlane, ISO 25178-3's F-operator "LS plane"), or the region's mean
// height (Levelling::kNone). Moments are central (about the mean residual), which
// equals the reference's zero up to rounding. All lengths in mm.
//
// The sums are mergeable accumulators (the OpenVDB math::Stats pattern): add(value)
// and add(other). A region is reduced over a fixed row chunking with
// tbb::parallel_deterministic_reduce, so the result is the same bits whatever the
// thread count; a map too large to hold merges its bands' accumulators in order.
#pragma once

#include <cmath>
#include <cstdint>

#include "raycast/zmap.h"

namespace scallop {

// Count, mean, central moment sums M2..M4 (Pébay 2008's one-pass and pairwise update
// formulas), extremes and sum of |value| of a set of values.
class HeightMoments {
 public:
  void add(double value);
  void add(const HeightMoments& other);

  int64_t count() const { return n_; }
  double mean() const { return mean_; }
  double min() const { return min_; }
  double max() const { return max_; }
  double sumAbs() const { return sumAbs_; }
  double m2() const { return m2_; }  // sum of (v - mean)^2
  double m3() const { return m3_; }
  double m4() const { return m4_; }

 private:
  int64_t n_ = 0;
  double mean_ = 0, m2_ = 0, m3_ = 0, m4_ = 0;
  double min_ = HUGE_VAL, max_ = -HUGE_VAL, sumAbs_ = 0;
};

// The plane z = z0 + slopeX (x - x0) + slopeY (y - y0), mm; the flat plane at z0 for
// Levelling::kNone.
struct LevelPlane {
  double x0 = 0, y0 = 0, z0 = 0;
  double slopeX = 0, slopeY = 0;  // mm per mm
  double at(double x, double y) const { return z0 + slopeX * (x - x0) + slopeY * (y - y0); }
};

// Sums of the least-squares plane's normal equations, in coordinates relative to a
// fixed point (x0, y0) (the region's centre) so that they stay well conditioned.
class PlaneSums {
 public:
  PlaneSums() = default;
  PlaneSums(double x0, double y0) : x0_(x0), y0_(y0) {}
  void add(double x, double y, double z);
  void add(const PlaneSums& other);  // same (x0, y0)
  int64_t count() const { return n_; }
  // The least-squares plane; with fitSlopes = false the flat plane at the mean height.
  // A region one cell wide gets slope 0 across it (the normal equations are singular).
  LevelPlane solve(bool fitSlopes) const;

 private:
  double x0_ = 0, y0_ = 0;
  int64_t n_ = 0;
  double sx_ = 0, sy_ = 0, sz_ = 0, sxx_ = 0, sxy_ = 0, syy_ = 0, sxz_ = 0, syz_ = 0;
};

enum class Levelling { kNone, kPlane };

// Cells [i0, i1) x [j0, j1) of a map (ZMap indices, j = 0 smallest y).
struct CellRegion {
  int64_t i0 = 0, j0 = 0, i1 = 0, j1 = 0;
  int64_t cells() const { return (i1 - i0) * (j1 - j0); }
};

CellRegion wholeMap(const GridSpec& grid);
// The cells whose centres lie in [x0, x1] x [y0, y1] (mm). Throws InputError(where, ...)
// if the rectangle is not ordered (x0 < x1, y0 < y1) or holds no cell centre.
CellRegion regionOfRectangle(const GridSpec& grid, double x0, double y0, double x1, double y1,
                             const char* where);

struct SurfaceStats {
  Levelling levelling = Levelling::kPlane;
  LevelPlane plane;  // the reference surface
  int64_t cells = 0;
  double areaMm2 = 0;
  double sa = NAN, sq = NAN, sp = NAN, sv = NAN, sz = NAN;  // mm
  double ssk = NAN, sku = NAN;                              // dimensionless
};

// Both leave out cells without a height (NaN: a frame's lines that miss the stock).
// Plane sums of the region's cell centres and heights (relative to the region's centre).
PlaneSums planeSums(const ZMap& map, const CellRegion& region);
// Moments of the heights minus `reference` over the region.
HeightMoments residualMoments(const ZMap& map, const CellRegion& region,
                              const LevelPlane& reference);

// The ISO 25178-2 height parameters from the moments of heights minus `reference`.
// Sp and Sv are measured from the residuals' mean (zero for a least-squares reference,
// the mean height for moments of raw heights, reference z0 = 0), which is added to the
// returned plane. Sa needs |residual| about the final reference, known only in a second
// pass: with hasSa = false it stays NaN.
SurfaceStats statsFromMoments(const HeightMoments& residuals, const LevelPlane& reference,
                              double cellAreaMm2, bool hasSa);

// Two passes over the region: the reference surface, then the residuals' moments.
SurfaceStats surfaceStats(const ZMap& map, const CellRegion& region, Levelling levelling);

}  // namespace scallop
