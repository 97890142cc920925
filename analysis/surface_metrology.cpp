// Areal height parameters (surface_metrology.h).
#include "analysis/surface_metrology.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>

#include <Eigen/Dense>
#include <algorithm>
#include <initializer_list>
#include <string>

#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

namespace {

// Rows per leaf of the reduction tree. Fixed (never derived from the thread count):
// with tbb::simple_partitioner the ranges are split at the same places every run and
// parallel_deterministic_reduce joins them in the same tree, so the sums are the same
// bits on 1 or 64 threads.
constexpr int64_t kRowsPerLeaf = 4;

// Numbers in messages, to 10 significant digits.
std::string numbers(std::initializer_list<double> values) {
  std::string s;
  for (double v : values) s += (s.empty() ? "" : " ") + formatNumber(v);
  return s;
}

template <class Accumulator, class RowFn>
Accumulator reduceRows(const CellRegion& region, const Accumulator& empty, const RowFn& addRow) {
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<int64_t>(region.j0, region.j1, kRowsPerLeaf), empty,
      [&](const tbb::blocked_range<int64_t>& rows, Accumulator acc) {
        for (int64_t j = rows.begin(); j < rows.end(); ++j) addRow(j, acc);
        return acc;
      },
      [](Accumulator a, const Accumulator& b) {
        a.add(b);
        return a;
      },
      tbb::simple_partitioner());
}

}  // namespace

void HeightMoments::add(double v) {
  // Pébay (2008) eq. 1.5 with one new value; the same as add(other) with other.n = 1.
  const int64_t n1 = n_;
  ++n_;
  const double n = double(n_);
  const double delta = v - mean_;
  const double deltaN = delta / n;
  const double deltaN2 = deltaN * deltaN;
  const double term1 = delta * deltaN * double(n1);
  mean_ += deltaN;
  m4_ += term1 * deltaN2 * (n * n - 3 * n + 3) + 6 * deltaN2 * m2_ - 4 * deltaN * m3_;
  m3_ += term1 * deltaN * (n - 2) - 3 * deltaN * m2_;
  m2_ += term1;
  min_ = std::min(min_, v);
  max_ = std::max(max_, v);
  sumAbs_ += std::abs(v);
}

void HeightMoments::add(const HeightMoments& o) {
  if (o.n_ == 0) return;
  if (n_ == 0) {
    *this = o;
    return;
  }
  // Pébay (2008) eqs. 2.1-2.3, pairwise update of the central moment sums.
  const double na = double(n_), nb = double(o.n_), n = na + nb;
  const double d = o.mean_ - mean_, d2 = d * d;
  const double m2 = m2_ + o.m2_ + d2 * na * nb / n;
  const double m3 =
      m3_ + o.m3_ + d2 * d * na * nb * (na - nb) / (n * n) + 3 * d * (na * o.m2_ - nb * m2_) / n;
  const double m4 = m4_ + o.m4_ + d2 * d2 * na * nb * (na * na - na * nb + nb * nb) / (n * n * n) +
                    6 * d2 * (na * na * o.m2_ + nb * nb * m2_) / (n * n) +
                    4 * d * (na * o.m3_ - nb * m3_) / n;
  mean_ += d * nb / n;
  m2_ = m2;
  m3_ = m3;
  m4_ = m4;
  n_ += o.n_;
  min_ = std::min(min_, o.min_);
  max_ = std::max(max_, o.max_);
  sumAbs_ += o.sumAbs_;
}

void PlaneSums::add(double x, double y, double z) {
  const double u = x - x0_, v = y - y0_;
  ++n_;
  sx_ += u;
  sy_ += v;
  sz_ += z;
  sxx_ += u * u;
  sxy_ += u * v;
  syy_ += v * v;
  sxz_ += u * z;
  syz_ += v * z;
}

void PlaneSums::add(const PlaneSums& o) {
  n_ += o.n_;
  sx_ += o.sx_;
  sy_ += o.sy_;
  sz_ += o.sz_;
  sxx_ += o.sxx_;
  sxy_ += o.sxy_;
  syy_ += o.syy_;
  sxz_ += o.sxz_;
  syz_ += o.syz_;
}

LevelPlane PlaneSums::solve(bool fitSlopes) const {
  LevelPlane p;
  p.x0 = x0_;
  p.y0 = y0_;
  if (n_ == 0) return p;
  if (!fitSlopes) {
    p.z0 = sz_ / double(n_);
    return p;
  }
  // Normal equations of min sum (c + a u + b v - z)^2; the minimum-norm solution
  // gives slope 0 along a direction the region does not extend in.
  Eigen::Matrix3d a;
  a << double(n_), sx_, sy_, sx_, sxx_, sxy_, sy_, sxy_, syy_;
  const Eigen::Vector3d rhs(sz_, sxz_, syz_);
  const Eigen::Vector3d sol = a.completeOrthogonalDecomposition().solve(rhs);
  p.z0 = sol[0];
  p.slopeX = sol[1];
  p.slopeY = sol[2];
  return p;
}

CellRegion wholeMap(const GridSpec& grid) {
  return {0, 0, grid.nx, grid.ny};
}

CellRegion regionOfRectangle(const GridSpec& g, double x0, double y0, double x1, double y1,
                             const char* where) {
  if (!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1)) ||
      !(x0 < x1) || !(y0 < y1))
    throw InputError(where, "expected x0 y0 x1 y1 (mm) with x0 < x1 and y0 < y1, got " +
                                numbers({x0, y0, x1, y1}));
  // Cell i's centre is origin + (i + 1/2) s: the first index with centre >= x0 and
  // the last with centre <= x1, checked against the centres themselves (no rounding).
  auto first = [&](double lo, double origin, int64_t n, double (GridSpec::*centre)(int64_t) const) {
    int64_t i = std::clamp<int64_t>(int64_t(std::ceil((lo - origin) / g.spacing - 0.5)), 0, n);
    while (i > 0 && (g.*centre)(i - 1) >= lo) --i;
    while (i < n && (g.*centre)(i) < lo) ++i;
    return i;
  };
  auto end = [&](double hi, double origin, int64_t n, double (GridSpec::*centre)(int64_t) const) {
    int64_t i = std::clamp<int64_t>(int64_t(std::floor((hi - origin) / g.spacing - 0.5)) + 1, 0, n);
    while (i < n && (g.*centre)(i) <= hi) ++i;
    while (i > 0 && (g.*centre)(i - 1) > hi) --i;
    return i;
  };
  CellRegion r;
  r.i0 = first(x0, g.originX, g.nx, &GridSpec::cellCentreX);
  r.i1 = end(x1, g.originX, g.nx, &GridSpec::cellCentreX);
  r.j0 = first(y0, g.originY, g.ny, &GridSpec::cellCentreY);
  r.j1 = end(y1, g.originY, g.ny, &GridSpec::cellCentreY);
  if (r.i1 <= r.i0 || r.j1 <= r.j0)
    throw InputError(where, "the rectangle x0 y0 x1 y1 = " + numbers({x0, y0, x1, y1}) +
                                " mm holds no cell centre of the map, whose centres span " +
                                numbers({g.cellCentreX(0), g.cellCentreY(0),
                                         g.cellCentreX(g.nx - 1), g.cellCentreY(g.ny - 1)}) +
                                " mm");
  return r;
}

PlaneSums planeSums(const ZMap& map, const CellRegion& region) {
  const GridSpec& g = map.grid();
  const PlaneSums empty(0.5 * (g.cellCentreX(region.i0) + g.cellCentreX(region.i1 - 1)),
                        0.5 * (g.cellCentreY(region.j0) + g.cellCentreY(region.j1 - 1)));
  return reduceRows(region, empty, [&](int64_t j, PlaneSums& acc) {
    const double y = g.cellCentreY(j);
    for (int64_t i = region.i0; i < region.i1; ++i)
      if (!std::isnan(map.at(i, j))) acc.add(g.cellCentreX(i), y, map.at(i, j));
  });
}

HeightMoments residualMoments(const ZMap& map, const CellRegion& region,
                              const LevelPlane& reference) {
  const GridSpec& g = map.grid();
  return reduceRows(region, HeightMoments(), [&](int64_t j, HeightMoments& acc) {
    const double y = g.cellCentreY(j);
    for (int64_t i = region.i0; i < region.i1; ++i)
      if (!std::isnan(map.at(i, j))) acc.add(map.at(i, j) - reference.at(g.cellCentreX(i), y));
  });
}

SurfaceStats statsFromMoments(const HeightMoments& r, const LevelPlane& reference,
                              double cellAreaMm2, bool hasSa) {
  SurfaceStats s;
  s.plane = reference;
  s.cells = r.count();
  s.areaMm2 = double(r.count()) * cellAreaMm2;
  if (r.count() == 0) return s;
  const double n = double(r.count());
  s.plane.z0 += r.mean();
  // ISO 25178-2 eqs. for Sq, Ssk, Sku with the integrals as means over the cells.
  s.sq = std::sqrt(r.m2() / n);
  const double variance = r.m2() / n;
  s.ssk = variance > 0 ? (r.m3() / n) / (variance * s.sq) : 0.0;
  s.sku = variance > 0 ? (r.m4() / n) / (variance * variance) : 0.0;
  s.sp = r.max() - r.mean();
  s.sv = r.mean() - r.min();
  s.sz = s.sp + s.sv;
  if (hasSa) s.sa = r.sumAbs() / n;
  return s;
}

SurfaceStats surfaceStats(const ZMap& map, const CellRegion& region, Levelling levelling) {
  const LevelPlane plane = planeSums(map, region).solve(levelling == Levelling::kPlane);
  const double s = map.grid().spacing;
  SurfaceStats stats = statsFromMoments(residualMoments(map, region, plane), plane, s * s, true);
  stats.levelling = levelling;
  return stats;
}

}  // namespace scallop
