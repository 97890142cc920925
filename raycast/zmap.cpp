#include "raycast/zmap.h"

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace scallop {

GridSpec gridCovering(double minX, double minY, double maxX, double maxY, double spacing) {
  GridSpec g;
  g.originX = minX;
  g.originY = minY;
  g.spacing = spacing;
  // The 1e-9 guard keeps an extent that is an exact multiple of the spacing from
  // gaining a row to round-off (20 / 0.002 is 10000.000000000002 in double).
  g.nx = std::max<int64_t>(1, int64_t(std::ceil((maxX - minX) / spacing - 1e-9)));
  g.ny = std::max<int64_t>(1, int64_t(std::ceil((maxY - minY) / spacing - 1e-9)));
  return g;
}

ZMap::ZMap(const GridSpec& grid, double initialHeight) : grid_(grid) {
  // A large map asks the kernel for 2 MB pages before its first touch: 512 times fewer
  // page faults while it is filled (on a VM each costs microseconds: 0.8 s for the 3.2 GB
  // map of B1), and fewer TLB misses while tiles walk its rows. Only advice: where the
  // kernel has none to give, nothing changes.
  const size_t n = size_t(grid.cells());
  heights_.reserve(n);
  constexpr uintptr_t kHuge = uintptr_t(1) << 21;
  const uintptr_t begin = reinterpret_cast<uintptr_t>(heights_.data());
  const uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t last = (begin + n * sizeof(double)) & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  heights_.assign(n, initialHeight);
}

// Cells without material (NaN, a frame's lines that miss the stock) are left out:
// the first of the smallest (largest) of the others, NaN when there is none.
double ZMap::minHeight() const {
  if (heights_.empty()) return 0.0;
  double best = NAN;
  for (const double h : heights_)
    if (h < best || std::isnan(best)) best = h;
  return best;
}

double ZMap::maxHeight() const {
  if (heights_.empty()) return 0.0;
  double best = NAN;
  for (const double h : heights_)
    if (h > best || std::isnan(best)) best = h;
  return best;
}

}  // namespace scallop
