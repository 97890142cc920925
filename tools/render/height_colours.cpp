#include "tools/render/height_colours.h"

#include <algorithm>
#include <cmath>
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

// A strip along the edge that the cutter only grazed, or a few deep spots, would
// otherwise take most of the colours and leave the scallops in one shade. The range is
// the 0.5th to the 99.5th percentile, narrowed to Tukey's far fences (3 interquartile
// ranges beyond the quartiles), so a tail of a few percent of the cells cannot stretch
// it either. Falls back to the whole range when the cut region is empty or flat.
std::pair<double, double> robustRange(const HeightRaster& p) {
  const double top = *std::max_element(p.z.begin(), p.z.end());
  const double bottom = *std::min_element(p.z.begin(), p.z.end());
  std::vector<double> cut;
  for (double z : p.z)
    if (z < top) cut.push_back(z);
  if (cut.empty()) return {bottom, top};
  auto quantile = [&cut](double q) {
    auto it = cut.begin() + long(std::floor(q * double(cut.size() - 1)));
    std::nth_element(cut.begin(), it, cut.end());
    return *it;
  };
  const double q1 = quantile(0.25), q3 = quantile(0.75), fence = 3 * (q3 - q1);
  const double lo = std::max(quantile(0.005), q1 - fence);
  const double hi = std::min(quantile(0.995), q3 + fence);
  return hi > lo ? std::pair<double, double>{lo, hi} : std::pair<double, double>{bottom, top};
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
