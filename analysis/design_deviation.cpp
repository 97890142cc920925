#include "analysis/design_deviation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "analysis/gouge_check.h"

namespace scallop {

DesignComparison compareWithDesign(const ZMap& machined, const MeshIndex& design,
                                   double gougeTolerance) {
  DesignComparison c;
  c.grid = machined.grid();
  c.tolerance = gougeTolerance;
  c.deviation = std::move(designHeights(design, c.grid).heights());
  const GridSpec& g = c.grid;
  const double cellArea = g.spacing * g.spacing;
  DeviationSummary& s = c.summary;
  double sum = 0, sumSq = 0;
  s.min = HUGE_VAL, s.max = -HUGE_VAL;
  for (size_t k = 0; k < c.deviation.size(); ++k) {
    double& d = c.deviation[k];
    if (std::isnan(d)) continue;
    d = machined.heights()[k] - d;
    if (std::isnan(d)) continue;  // no material on the cell's line (a frame's void cell)
    ++s.cells;
    sum += d, sumSq += d * d;
    s.min = std::min(s.min, d), s.max = std::max(s.max, d);
    if (d < -gougeTolerance) ++s.overcutCells;
    if (d > gougeTolerance) ++s.undercutCells;
  }
  if (s.cells == 0) {
    s.min = s.max = 0;
  } else {
    s.mean = sum / double(s.cells);
    s.rms = std::sqrt(sumSq / double(s.cells));
  }
  s.overcutAreaMm2 = double(s.overcutCells) * cellArea;
  s.undercutAreaMm2 = double(s.undercutCells) * cellArea;

  // Gouge regions: 4-connected components of cells below -tolerance.
  std::vector<char> seen(c.deviation.size(), 0);
  std::vector<int64_t> stack;
  auto gouging = [&](int64_t k) { return c.deviation[size_t(k)] < -gougeTolerance; };
  for (int64_t start = 0; start < g.cells(); ++start) {
    if (seen[size_t(start)] || !gouging(start)) continue;
    Gouge gouge;
    int64_t deepest = start;
    stack.assign(1, start);
    seen[size_t(start)] = 1;
    while (!stack.empty()) {
      const int64_t k = stack.back();
      stack.pop_back();
      ++gouge.cells;
      if (c.deviation[size_t(k)] < c.deviation[size_t(deepest)]) deepest = k;
      const int64_t i = k % g.nx, j = k / g.nx;
      const int64_t next[4] = {i > 0 ? k - 1 : -1, i + 1 < g.nx ? k + 1 : -1, j > 0 ? k - g.nx : -1,
                               j + 1 < g.ny ? k + g.nx : -1};
      for (int64_t n : next)
        if (n >= 0 && !seen[size_t(n)] && gouging(n)) seen[size_t(n)] = 1, stack.push_back(n);
    }
    gouge.areaMm2 = double(gouge.cells) * cellArea;
    gouge.i = deepest % g.nx, gouge.j = deepest / g.nx;
    gouge.x = g.cellCentreX(gouge.i), gouge.y = g.cellCentreY(gouge.j);
    gouge.machinedZ = machined.at(gouge.i, gouge.j);
    gouge.depth = -c.deviation[size_t(deepest)];
    gouge.designZ = gouge.machinedZ + gouge.depth;
    c.gouges.push_back(gouge);
  }
  std::sort(c.gouges.begin(), c.gouges.end(),
            [](const Gouge& a, const Gouge& b) { return a.depth > b.depth; });
  return c;
}

// --- MoveFinder ----------------------------------------------------------------

struct MoveFinder::Impl {
  struct Entry {
    SweptMove segment;
    size_t move;
  };
  std::vector<Entry> entries;
  std::vector<std::vector<uint32_t>> firstEntry;  // per move: its entries
  // Uniform buckets over the areas' bounds: entry indices whose xy bounds meet each.
  double x0 = 0, y0 = 0, cell = 1;
  int64_t nx = 0, ny = 0;
  std::vector<std::vector<uint32_t>> buckets;
  std::vector<int64_t> moveToSlot;  // index into firstEntry, -1: not swept

  int64_t clampX(double x) const {
    return std::clamp<int64_t>(int64_t(std::floor((x - x0) / cell)), 0, nx - 1);
  }
  int64_t clampY(double y) const {
    return std::clamp<int64_t>(int64_t(std::floor((y - y0) / cell)), 0, ny - 1);
  }
};

MoveFinder::MoveFinder(const Cutter& cutter, const ToolPath& path, const std::vector<Box3>& areas)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.moveToSlot.assign(path.moves.size(), -1);
  if (areas.empty()) return;
  Box3 all;
  for (const Box3& a : areas) all.extend(a.min), all.extend(a.max);
  m.cell = std::max(cutter.radius, 1e-3);
  m.x0 = all.min.x, m.y0 = all.min.y;
  m.nx = std::max<int64_t>(1, int64_t(std::ceil((all.max.x - all.min.x) / m.cell)) + 1);
  m.ny = std::max<int64_t>(1, int64_t(std::ceil((all.max.y - all.min.y) / m.cell)) + 1);
  // Keep the bucket grid modest whatever the areas' spread.
  while (m.nx * m.ny > 4'000'000) {
    m.cell *= 2;
    m.nx = int64_t(std::ceil((all.max.x - all.min.x) / m.cell)) + 1;
    m.ny = int64_t(std::ceil((all.max.y - all.min.y) / m.cell)) + 1;
  }
  std::vector<char> wanted(size_t(m.nx * m.ny), 0);
  for (const Box3& a : areas)
    for (int64_t j = m.clampY(a.min.y); j <= m.clampY(a.max.y); ++j)
      for (int64_t i = m.clampX(a.min.x); i <= m.clampX(a.max.x); ++i)
        wanted[size_t(j * m.nx + i)] = 1;
  m.buckets.resize(wanted.size());

  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& mv = path.moves[k];
    if (mv.rapid) continue;
    const ToolPath one = path.single(k);
    // A cheap xy box first: the tip's path grown by the cutter's reach.
    const double lean = std::max(std::hypot(mv.from.axis.x, mv.from.axis.y),
                                 std::hypot(mv.to.axis.x, mv.to.axis.y));
    const double reach = cutter.radius + cutter.fluteLength * lean;
    Box3 tips;
    tips.extend(mv.from.tip), tips.extend(mv.to.tip);
    if (mv.arc > 0 && mv.arc <= path.arcs.size()) tips = path.arcs[mv.arc - 1].bounds();
    const double lx = tips.min.x - reach, hx = tips.max.x + reach;
    const double ly = tips.min.y - reach, hy = tips.max.y + reach;
    if (hx < all.min.x || lx > all.max.x || hy < all.min.y || ly > all.max.y) continue;
    bool near = false;
    for (int64_t j = m.clampY(ly); j <= m.clampY(hy) && !near; ++j)
      for (int64_t i = m.clampX(lx); i <= m.clampX(hx) && !near; ++i)
        near = wanted[size_t(j * m.nx + i)];
    if (!near) continue;
    m.moveToSlot[k] = int64_t(m.firstEntry.size());
    m.firstEntry.emplace_back();
    for (const SweptMove& s : sweepToolPath(cutter, one)) {
      const uint32_t e = uint32_t(m.entries.size());
      m.entries.push_back({s, k});
      m.firstEntry.back().push_back(e);
      const Box3 b = s.bounds();
      for (int64_t j = m.clampY(b.min.y); j <= m.clampY(b.max.y); ++j)
        for (int64_t i = m.clampX(b.min.x); i <= m.clampX(b.max.x); ++i)
          if (wanted[size_t(j * m.nx + i)]) m.buckets[size_t(j * m.nx + i)].push_back(e);
    }
  }
}

MoveFinder::~MoveFinder() = default;

size_t MoveFinder::sweptMoves() const {
  return impl_->firstEntry.size();
}

std::vector<size_t> MoveFinder::movesAt(double x, double y, double z, double tolerance) const {
  const Impl& m = *impl_;
  std::vector<size_t> out;
  if (m.buckets.empty()) return out;
  const int64_t i = int64_t(std::floor((x - m.x0) / m.cell));
  const int64_t j = int64_t(std::floor((y - m.y0) / m.cell));
  if (i < 0 || j < 0 || i >= m.nx || j >= m.ny) return out;
  for (uint32_t e : m.buckets[size_t(j * m.nx + i)]) {
    const Impl::Entry& entry = m.entries[e];
    const Box3 b = entry.segment.bounds();
    if (x < b.min.x || x > b.max.x || y < b.min.y || y > b.max.y) continue;
    const LowestPoint lp = entry.segment.lowestPoint(x, y);
    if (lp.hit && lp.z <= z + tolerance) out.push_back(entry.move);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double MoveFinder::moveHeight(size_t move, double x, double y) const {
  const Impl& m = *impl_;
  if (move >= m.moveToSlot.size() || m.moveToSlot[move] < 0) return HUGE_VAL;
  double best = HUGE_VAL;
  for (uint32_t e : m.firstEntry[size_t(m.moveToSlot[move])]) {
    const LowestPoint lp = m.entries[e].segment.lowestPoint(x, y);
    if (lp.hit) best = std::min(best, lp.z);
  }
  return best;
}

void attributeGouges(DesignComparison& comparison, const ZMap& machined, const Cutter& cutter,
                     const ToolPath& path, int cellsPerGouge) {
  if (comparison.gouges.empty()) return;
  const GridSpec& g = comparison.grid;
  // The deepest cells of each region: a flood from its deepest cell, ranked by depth.
  std::vector<std::vector<int64_t>> cells(comparison.gouges.size());
  std::vector<Box3> areas;
  const double tol = comparison.tolerance;
  std::vector<char> seen(comparison.deviation.size(), 0);
  for (size_t r = 0; r < comparison.gouges.size(); ++r) {
    const Gouge& gouge = comparison.gouges[r];
    std::vector<int64_t> region, stack{gouge.j * g.nx + gouge.i}, visited;
    auto mark = [&](int64_t k) {
      if (seen[size_t(k)]) return false;
      seen[size_t(k)] = 1;
      visited.push_back(k);
      return true;
    };
    mark(stack[0]);
    while (!stack.empty() && region.size() < 4096) {
      const int64_t k = stack.back();
      stack.pop_back();
      region.push_back(k);
      const int64_t i = k % g.nx, j = k / g.nx;
      const int64_t next[4] = {i > 0 ? k - 1 : -1, i + 1 < g.nx ? k + 1 : -1, j > 0 ? k - g.nx : -1,
                               j + 1 < g.ny ? k + g.nx : -1};
      for (int64_t n : next)
        if (n >= 0 && comparison.deviation[size_t(n)] < -tol && mark(n)) stack.push_back(n);
    }
    for (int64_t k : visited) seen[size_t(k)] = 0;
    std::sort(region.begin(), region.end(), [&](int64_t a, int64_t b) {
      return comparison.deviation[size_t(a)] < comparison.deviation[size_t(b)];
    });
    if (int64_t(region.size()) > cellsPerGouge) region.resize(size_t(cellsPerGouge));
    for (int64_t k : region) {
      const double x = g.cellCentreX(k % g.nx), y = g.cellCentreY(k / g.nx);
      Box3 b;
      b.extend({x - g.spacing, y - g.spacing, 0});
      b.extend({x + g.spacing, y + g.spacing, 0});
      areas.push_back(b);
    }
    cells[r] = std::move(region);
  }
  const MoveFinder finder(cutter, path, areas);
  tbb::parallel_for(size_t(0), comparison.gouges.size(), [&](size_t r) {
    std::vector<size_t>& moves = comparison.gouges[r].moves;
    for (int64_t k : cells[r]) {
      const int64_t i = k % g.nx, j = k / g.nx;
      // The merged segments of the simulation and the per-move ones agree to round-off.
      for (size_t mv : finder.movesAt(g.cellCentreX(i), g.cellCentreY(j), machined.at(i, j), 1e-7))
        moves.push_back(mv);
    }
    std::sort(moves.begin(), moves.end());
    moves.erase(std::unique(moves.begin(), moves.end()), moves.end());
  });
}

}  // namespace scallop
