#include "tools/render/height_colours.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace scallop {

using png::Rgb;

// Sampled at t = 0, 0.1, ..., 1 and interpolated linearly.
Rgb viridis(double t) {
  static constexpr Rgb kTable[] = {{68, 1, 84},    {72, 36, 117},  {65, 68, 135},  {53, 95, 141},
                                   {42, 120, 142}, {33, 145, 140}, {34, 168, 132}, {68, 191, 112},
                                   {122, 209, 81}, {189, 223, 38}, {253, 231, 37}};
  constexpr int n = int(sizeof(kTable) / sizeof(kTable[0]));
  if (!(t > 0)) t = 0;  // also catches NaN
  if (t > 1) t = 1;
  const double x = t * (n - 1);
  const int k = std::min(n - 2, int(x));
  const double f = x - k;
  auto mix = [f](uint8_t a, uint8_t b) { return uint8_t(std::lround(a + (b - a) * f)); };
  return {mix(kTable[k].r, kTable[k + 1].r), mix(kTable[k].g, kTable[k + 1].g),
          mix(kTable[k].b, kTable[k + 1].b)};
}

namespace {

// Marks, along one line of cells (`step` apart from `first`, `n` of them), every cell
// of a strictly falling run that starts at the line's end or beside an uncut cell
// (z >= top) or one without material (NaN), walking away from it; uncut cells
// themselves are marked too.
void markFallingRuns(const std::vector<double>& z, size_t first, ptrdiff_t step, int n, double top,
                     std::vector<bool>& marked) {
  bool falling = true;
  double previous = HUGE_VAL;
  for (int k = 0; k < n; ++k) {
    const size_t c = size_t(ptrdiff_t(first) + k * step);
    if (z[c] >= top || std::isnan(z[c])) {  // uncut, or no material: an edge
      marked[c] = true, falling = true, previous = HUGE_VAL;
    } else if (falling && z[c] < previous) {
      marked[c] = true, previous = z[c];
    } else {
      falling = false;
    }
  }
}

// The cells that fall from the map's edge or from an uncut cell along a row or a
// column, in either direction: the flank a cutter's side left beside its outermost
// pass (default job: the bull's corner rising 0.45 mm over a few tenths of a mm along
// the north edge). It can be several percent of the map and its heights form a long
// tail that no percentile leaves out. A machined field's own heights (scallops, feed
// marks) rise again within one period, so of them only the half period next to the
// edge is marked, and its heights recur inside.
std::vector<bool> edgeFlanks(const HeightRaster& p, double top) {
  std::vector<bool> marked(p.z.size(), false);
  const size_t w = size_t(p.w), h = size_t(p.h);
  for (size_t r = 0; r < h; ++r) {
    markFallingRuns(p.z, r * w, 1, p.w, top, marked);
    markFallingRuns(p.z, r * w + w - 1, -1, p.w, top, marked);
  }
  for (size_t a = 0; a < w; ++a) {
    markFallingRuns(p.z, a, ptrdiff_t(w), p.h, top, marked);
    markFallingRuns(p.z, (h - 1) * w + a, -ptrdiff_t(w), p.h, top, marked);
  }
  return marked;
}

}  // namespace

// Edge flanks, or a few deep spots, would otherwise take most of the colours and leave
// the scallops in one shade. The cut cells off the edge flanks (all cut cells when the
// flanks are half of them or more: then the flank is the surface, a bowl or a tilted
// plane) give the range: the 0.5th to the 99.5th percentile, narrowed to Tukey's far
// fences (3 interquartile ranges beyond the quartiles), so a tail of a few percent of
// the cells cannot stretch it either. Falls back to the whole range when the cut
// region is empty or flat.
std::pair<double, double> robustRange(const HeightRaster& p, double uncutHeight) {
  // Cells without material (NaN) take no part.
  double highest = -HUGE_VAL, bottom = HUGE_VAL;
  for (double z : p.z)
    if (!std::isnan(z)) highest = std::max(highest, z), bottom = std::min(bottom, z);
  if (bottom > highest) return {0.0, 0.0};  // no cell holds material
  const double top = std::isnan(uncutHeight) ? highest : uncutHeight;
  const std::vector<bool> flank = edgeFlanks(p, top);
  std::vector<double> cut, inner;
  for (size_t c = 0; c < p.z.size(); ++c) {
    if (!(p.z[c] < top)) continue;
    cut.push_back(p.z[c]);
    if (!flank[c]) inner.push_back(p.z[c]);
  }
  if (2 * inner.size() > cut.size()) cut.swap(inner);
  if (cut.empty()) return {bottom, highest};
  auto quantile = [&cut](double q) {
    auto it = cut.begin() + long(std::floor(q * double(cut.size() - 1)));
    std::nth_element(cut.begin(), it, cut.end());
    return *it;
  };
  const double q1 = quantile(0.25), q3 = quantile(0.75), fence = 3 * (q3 - q1);
  const double lo = std::max(quantile(0.005), q1 - fence);
  const double hi = std::min(quantile(0.995), q3 + fence);
  return hi > lo ? std::pair<double, double>{lo, hi} : std::pair<double, double>{bottom, highest};
}

Rgb shaded(Rgb c, double factor, double maxFactor) {
  // maxFactor is 1 under a light straight above: then no facet is lit more than a floor.
  const double towardsWhite =
      factor > 1 && maxFactor > 1 ? 0.6 * (factor - 1) / (maxFactor - 1) : 0.0;
  auto s = [&](uint8_t v) {
    const double x = factor > 1 ? v + (255 - v) * towardsWhite : v * factor;
    return uint8_t(std::clamp(std::lround(x), 0L, 255L));
  };
  return {s(c.r), s(c.g), s(c.b)};
}

}  // namespace scallop
