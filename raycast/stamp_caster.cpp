#include "raycast/stamp_caster.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "raycast/cell_tiles.h"

namespace scallop {

namespace {

// One stamp: the stationary cutter of move `segment` at one pose.
struct Stamp {
  Vec3 tip, axis;
  double lowest;          // its lowest point's z, mm: cells at or below it are untouched
  double x0, x1, y0, y1;  // xy footprint box, mm
  uint32_t segment;
};

// Cells whose centres can lie in [lo, hi] along one axis (one cell of margin, which
// only costs a miss), clipped to [0, n).
void cellRange(double lo, double hi, double origin, double s, int64_t n, int64_t& a, int64_t& b) {
  a = std::max<int64_t>(0, int64_t(std::floor((lo - origin) / s - 0.5)) - 1);
  b = std::min<int64_t>(n, int64_t(std::ceil((hi - origin) / s - 0.5)) + 2);
}

}  // namespace

double stampStepFor(const Cutter& cutter, const Vec3& axis, double tolerance) {
  double step;
  switch (cutter.type) {
    case CutterType::Ball:
      step = std::sqrt(8 * tolerance * cutter.radius);
      break;
    case CutterType::Bull:
      step = std::sqrt(8 * tolerance * cutter.cornerRadius);
      break;
    case CutterType::Flat:
    default: {
      const double tanAlpha = std::sqrt(std::max(0.0, 1 - axis.z * axis.z)) / std::fabs(axis.z);
      step = std::sqrt(8 * tolerance * cutter.radius);
      if (tanAlpha > 0) step = std::min(step, tolerance / tanAlpha);
      break;
    }
  }
  return 0.5 * step;  // Meusnier margin, see the header
}

StampStats stampZMap(const std::vector<SweptMove>& segments, ZMap& map,
                     const StampOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const GridSpec& g = map.grid();
  StampStats stats;
  stats.cells = g.cells();
  if (g.cells() == 0) return stats;
  const double ceiling = map.maxHeight();
  const double mapX1 = g.originX + g.nx * g.spacing, mapY1 = g.originY + g.ny * g.spacing;

  // --- The stamps, in path order (earlier stamps lower cells first, which lets later
  // ones skip cells already below their lowest point). ------------------------------
  std::vector<Stamp> stamps;
  double widest = 0;
  stats.minStep = HUGE_VAL;
  for (size_t k = 0; k < segments.size(); ++k) {
    const SweptMove& seg = segments[k];
    const Cutter& c = seg.cutter();
    const PoseCurve& curve = seg.curve();
    // A turning axis moves the cutter's lower part (within R of the tip) by up to
    // R omega per unit t besides the tip's motion: the stamps are spaced for both.
    const double step =
        options.step > 0 ? options.step : stampStepFor(c, curve.axis(0), options.tolerance);
    stats.minStep = std::min(stats.minStep, step);
    const double travel = length(seg.end() - seg.start()) + c.radius * curve.turnRate();
    const int64_t n = std::max<int64_t>(1, int64_t(std::ceil(travel / step)));
    for (int64_t i = 0; i <= n; ++i) {
      Stamp s;
      const double t = double(i) / double(n);
      s.tip = curve.tip(t);
      s.axis = curve.axis(t);
      const Vec3& a = s.axis;
      const double lowest = cutterSupport(c, a, {0, 0, -1}).z;
      const double bx0 = cutterSupport(c, a, {-1, 0, 0}).x, bx1 = cutterSupport(c, a, {1, 0, 0}).x;
      const double by0 = cutterSupport(c, a, {0, -1, 0}).y, by1 = cutterSupport(c, a, {0, 1, 0}).y;
      widest = std::max({widest, bx1 - bx0, by1 - by0});
      s.lowest = s.tip.z + lowest;
      s.x0 = s.tip.x + bx0, s.x1 = s.tip.x + bx1, s.y0 = s.tip.y + by0, s.y1 = s.tip.y + by1;
      s.segment = uint32_t(k);
      if (s.lowest >= ceiling || s.x1 < g.originX || s.x0 > mapX1 || s.y1 < g.originY ||
          s.y0 > mapY1)
        continue;
      stamps.push_back(s);
    }
  }
  stats.positions = stamps.size();
  if (stamps.empty()) {
    stats.minStep = std::isfinite(stats.minStep) ? stats.minStep : 0;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats;
  }

  // --- Buckets at least as wide as a footprint and a tile: a stamp lands in at most
  // four, and a tile finds its stamps in at most four. ---------------------------------
  const int64_t tile = std::max<int64_t>(1, options.tileCells);
  const double bucket = std::max(widest, double(tile) * g.spacing) * (1 + 1e-9);
  const int64_t nbx = std::max<int64_t>(1, int64_t(std::ceil((mapX1 - g.originX) / bucket)));
  const int64_t nby = std::max<int64_t>(1, int64_t(std::ceil((mapY1 - g.originY) / bucket)));
  auto bucketOf = [&](double v, double origin, int64_t n) {
    return std::clamp<int64_t>(int64_t(std::floor((v - origin) / bucket)), 0, n - 1);
  };
  std::vector<std::vector<uint32_t>> buckets(size_t(nbx * nby));
  for (size_t k = 0; k < stamps.size(); ++k) {
    const Stamp& s = stamps[k];
    for (int64_t by = bucketOf(s.y0, g.originY, nby); by <= bucketOf(s.y1, g.originY, nby); ++by)
      for (int64_t bx = bucketOf(s.x0, g.originX, nbx); bx <= bucketOf(s.x1, g.originX, nbx); ++bx)
        buckets[size_t(by * nbx + bx)].push_back(uint32_t(k));
  }

  // --- Tiles of cells, in parallel (cell_tiles.h); min() makes the order of stamps
  // irrelevant to the result. ----------------------------------------------------------
  const uint64_t evaluations = forEachCellTile(
      g, tile, options.progress, [&](int64_t i0, int64_t i1, int64_t j0, int64_t j1) {
        // The tile's extent (cellRange below uses the same cell edges).
        const double x0 = g.originX + double(i0) * g.spacing,
                     x1 = g.originX + double(i1) * g.spacing;
        const double y0 = g.originY + double(j0) * g.spacing,
                     y1 = g.originY + double(j1) * g.spacing;
        thread_local std::vector<uint32_t> mine;
        mine.clear();
        for (int64_t by = bucketOf(y0, g.originY, nby); by <= bucketOf(y1, g.originY, nby); ++by)
          for (int64_t bx = bucketOf(x0, g.originX, nbx); bx <= bucketOf(x1, g.originX, nbx);
               ++bx) {
            const std::vector<uint32_t>& b = buckets[size_t(by * nbx + bx)];
            mine.insert(mine.end(), b.begin(), b.end());
          }
        std::sort(mine.begin(), mine.end());
        mine.erase(std::unique(mine.begin(), mine.end()), mine.end());

        uint64_t evals = 0;
        for (uint32_t k : mine) {
          const Stamp& s = stamps[k];
          if (s.x1 < x0 || s.x0 > x1 || s.y1 < y0 || s.y0 > y1) continue;
          const SweptMove& seg = segments[s.segment];
          int64_t a0, a1, b0, b1;
          cellRange(s.x0, s.x1, g.originX, g.spacing, i1, a0, a1);
          cellRange(s.y0, s.y1, g.originY, g.spacing, j1, b0, b1);
          a0 = std::max(a0, i0), b0 = std::max(b0, j0);
          for (int64_t j = b0; j < b1; ++j) {
            const double y = g.cellCentreY(j) - s.tip.y;
            for (int64_t i = a0; i < a1; ++i) {
              double& h = map.at(i, j);
              if (h <= s.lowest) continue;  // this stamp cannot go lower here
              ++evals;
              const LowestPoint lp =
                  cutterLowestPoint(seg.cutter(), s.axis, g.cellCentreX(i) - s.tip.x, y);
              if (lp.hit) h = std::min(h, lp.z + s.tip.z);
            }
          }
        }
        return evals;
      });

  stats.exactEvaluations = evaluations;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return stats;
}

StampSimulationResult simulateStamped(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                      const GridSpec& grid, const StampOptions& options) {
  const std::vector<SweptMove> segments = sweepToolPath(cutter, path);
  StampSimulationResult result;
  result.segments = segments.size();
  result.map = ZMap(grid, stock.max.z);
  result.stamp = stampZMap(segments, result.map, options);
  return result;
}

}  // namespace scallop
