// preview.png: a shaded, colour-mapped picture of a ZMap with a colour bar and a
// scale bar. Canvas, font and PNG writing are in tools/render/png_canvas.h.
#include "tools/render/preview_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sweep/input_error.h"
#include "tools/io/atomic_file.h"
#include "tools/render/png_canvas.h"

namespace scallop {

namespace {

using png::Canvas;
using png::formatValue;
using png::kBackground;
using png::kCapHeightPx;
using png::kFrame;
using png::kInk;
using png::niceBelow;
using png::Rgb;
using png::textWidth;
using png::writePng;

constexpr double kDegree = 3.14159265358979323846 / 180.0;  // radians

// Viridis (perceptually uniform, readable in grey and by colour-blind viewers),
// sampled at t = 0, 0.1, ..., 1 and interpolated linearly.
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

// Darkens by `factor` below 1; above 1 (slopes facing the light) blends towards
// white instead, so that highlights also show on the dark end of the colour map.
Rgb shaded(Rgb c, double factor, double maxFactor) {
  const double towardsWhite = factor > 1 ? 0.6 * (factor - 1) / (maxFactor - 1) : 0.0;
  auto s = [&](uint8_t v) {
    const double x = factor > 1 ? v + (255 - v) * towardsWhite : v * factor;
    return uint8_t(std::clamp(std::lround(x), 0L, 255L));
  };
  return {s(c.r), s(c.g), s(c.b)};
}

// The map reduced by an integer factor (block minimum), stored north up.
struct PreviewGrid {
  int w = 0, h = 0;
  double cellMm = 0;      // side of one preview cell
  std::vector<double> z;  // z[r * w + a], r = 0 is the largest y

  double at(int a, int r) const { return z[size_t(r) * size_t(w) + size_t(a)]; }
};

PreviewGrid reduce(const ZMap& map, int64_t k) {
  PreviewGrid p;
  p.w = int((map.nx() + k - 1) / k);
  p.h = int((map.ny() + k - 1) / k);
  p.cellMm = map.grid().spacing * double(k);
  p.z.assign(size_t(p.w) * size_t(p.h), HUGE_VAL);
  for (int64_t j = 0; j < map.ny(); ++j) {
    const size_t rowBase = size_t(p.h - 1 - j / k) * size_t(p.w);
    for (int64_t i = 0; i < map.nx(); ++i) {
      double& z = p.z[rowBase + size_t(i / k)];
      z = std::min(z, map.at(i, j));
    }
  }
  return p;
}

constexpr double kAmbient = 0.3;
constexpr double kLightElevation = 45.0 * kDegree;
// Shading factor of a face turned straight to the light.
const double kMaxShade = kAmbient + (1 - kAmbient) / std::sin(kLightElevation);

// Brightness factor per preview cell from a Lambertian light at the north-west,
// 45 degrees up. Scallops are micrometres high over millimetres, so slopes are
// exaggerated until a typical (75th percentile) non-zero slope looks like 35 degrees;
// 1.0 means "as lit as a flat floor".
std::vector<double> hillShade(const PreviewGrid& p) {
  const size_t n = size_t(p.w) * size_t(p.h);
  std::vector<double> gx(n), gy(n);
  for (int r = 0; r < p.h; ++r)
    for (int a = 0; a < p.w; ++a) {
      const int a0 = std::max(0, a - 1), a1 = std::min(p.w - 1, a + 1);
      const int r0 = std::max(0, r - 1), r1 = std::min(p.h - 1, r + 1);  // r0 is north
      const size_t idx = size_t(r) * size_t(p.w) + size_t(a);
      gx[idx] = a1 > a0 ? (p.at(a1, r) - p.at(a0, r)) / ((a1 - a0) * p.cellMm) : 0.0;
      gy[idx] = r1 > r0 ? (p.at(a, r0) - p.at(a, r1)) / ((r1 - r0) * p.cellMm) : 0.0;
    }

  std::vector<double> slopes;
  for (size_t i = 0; i < n; ++i) {
    const double s = std::hypot(gx[i], gy[i]);
    if (s > 1e-9) slopes.push_back(s);  // below 1 nm per mm is round-off, not shape
  }
  double exaggeration = 0;
  if (!slopes.empty()) {
    auto q = slopes.begin() + long(slopes.size() * 3 / 4);
    std::nth_element(slopes.begin(), q, slopes.end());
    exaggeration = std::tan(35.0 * kDegree) / *q;
  }

  const double lz = std::sin(kLightElevation);
  const double lxy = std::cos(kLightElevation) / std::sqrt(2.0);
  const double lx = -lxy, ly = lxy;  // towards the light: west (-x) and north (+y)
  std::vector<double> factor(n);
  for (size_t i = 0; i < n; ++i) {
    const double nx = -exaggeration * gx[i], ny = -exaggeration * gy[i];
    const double lambert =
        std::max(0.0, (nx * lx + ny * ly + lz) / std::sqrt(nx * nx + ny * ny + 1));
    factor[i] = kAmbient + (1 - kAmbient) * lambert / lz;
  }
  return factor;
}

// The colour range: robust percentiles of the cut region, the cells below the highest
// height (which is the uncut stock top on a simulated map). A strip along the edge that
// the cutter only grazed, or a few deep spots, would otherwise take most of the colours
// and leave the scallops in one shade. The range is the 0.5th to the 99.5th percentile,
// narrowed to Tukey's far fences (3 interquartile ranges beyond the quartiles), so a
// tail of a few percent of the cells cannot stretch it either. Falls back to the whole
// range when the cut region is empty or flat; values beyond take the end colours.
std::pair<double, double> robustRange(const PreviewGrid& p) {
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

struct Tick {
  double value;
  std::string label;
};

// Labels for the colour bar: min and max, and round values between them that leave
// room for the text.
std::vector<Tick> colourBarTicks(double zmin, double zmax, int barH, int textH) {
  const double range = zmax - zmin;
  const double largest = std::max(std::abs(zmin), std::abs(zmax));
  const bool micro = range > 0 ? range < 0.5 : largest < 0.5;
  const double unitPerMm = micro ? 1000.0 : 1.0;
  const std::string unit = micro ? "\u00b5m" : "mm";
  if (!(range > 0)) return {{zmin, formatValue(zmin * unitPerMm, micro ? 1 : 4, unit)}};

  double step = niceBelow(range * unitPerMm / 3);
  const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
  std::vector<Tick> ticks = {{zmax, formatValue(zmax * unitPerMm, decimals + 1, unit)},
                             {zmin, formatValue(zmin * unitPerMm, decimals + 1, unit)}};
  const double pxPerMm = (barH - 1) / range;
  const double minGapMm = (textH + 4) / pxPerMm;
  step /= unitPerMm;
  for (double v = std::ceil(zmin / step) * step; v < zmax; v += step) {
    bool fits = true;
    for (const Tick& t : ticks) fits = fits && std::abs(t.value - v) >= minGapMm;
    if (fits) ticks.push_back({v, formatValue(v * unitPerMm, decimals, unit)});
  }
  return ticks;
}

}  // namespace

void writePreviewPng(const ZMap& map, const std::string& path, const PreviewOptions& options) {
  if (map.nx() <= 0 || map.ny() <= 0) throw InputError(path, "cannot draw an empty height map");
  if (!(map.grid().spacing > 0) || !std::isfinite(map.grid().spacing))
    throw InputError(path, fmt::format("grid spacing {} mm is not positive", map.grid().spacing));
  const int maxPixels = std::max(16, options.maxPixels);
  const int64_t longSide = std::max(map.nx(), map.ny());
  const int64_t k = (longSide + maxPixels - 1) / maxPixels;
  const PreviewGrid grid = reduce(map, k);
  const int gridLong = std::max(grid.w, grid.h);
  const int up =
      std::max(1, std::min((options.minPixels + gridLong - 1) / gridLong, maxPixels / gridLong));
  const std::vector<double> light = hillShade(grid);
  const auto [cutLow, cutHigh] = robustRange(grid);
  const double zmin = std::isnan(options.zMin) ? cutLow : options.zMin;
  const double zmax = std::isnan(options.zMax) ? cutHigh : options.zMax;
  const double range = zmax - zmin;

  // Layout, px.
  constexpr int s = 2;  // font scale
  constexpr int pad = 16, barW = 24;
  const int textH = kCapHeightPx * s;
  const std::string& title = options.title;
  const int mapW = grid.w * up, mapH = grid.h * up;
  const int mapX = pad, mapY = pad + (title.empty() ? 0 : textH + 12);
  const int barH = std::max(mapH, 200);
  const int barX = mapX + mapW + 24;
  const std::vector<Tick> ticks = colourBarTicks(zmin, zmax, barH, textH);
  int labelW = 0;
  for (const Tick& t : ticks) labelW = std::max(labelW, textWidth(t.label, s));
  const int labelX = barX + barW + 10;

  const double mmPerPx = grid.cellMm / up;
  const double scaleMm = niceBelow(0.4 * mapW * mmPerPx);
  const int scalePx = std::max(1, int(std::lround(scaleMm / mmPerPx)));
  const std::string scaleLabel =
      scaleMm >= 1 ? fmt::format("{:g} mm", scaleMm) : fmt::format("{:g} \u00b5m", scaleMm * 1000);
  const int scaleY = mapY + barH + 18;

  const int width = std::max({labelX + labelW + pad, pad + textWidth(title, s) + pad,
                              mapX + scalePx + 10 + textWidth(scaleLabel, s) + pad});
  const int height = scaleY + textH + pad;
  Canvas canvas(width, height);
  canvas.fill(0, 0, width, height, kBackground);
  if (!title.empty()) canvas.text(pad, pad, title, s, kInk);

  // The map: each preview cell becomes an up x up square.
  for (int r = 0; r < grid.h; ++r)
    for (int a = 0; a < grid.w; ++a) {
      const double t = range > 0 ? (grid.at(a, r) - zmin) / range : 0.5;
      const Rgb c = shaded(viridis(t), light[size_t(r) * size_t(grid.w) + size_t(a)], kMaxShade);
      canvas.fill(mapX + a * up, mapY + r * up, up, up, c);
    }
  canvas.frame(mapX, mapY, mapW, mapH, kFrame);

  // Colour bar, high at the top, with ticks and labels.
  for (int y = 0; y < barH; ++y)
    canvas.fill(barX, mapY + y, barW, 1, viridis(range > 0 ? 1.0 - double(y) / (barH - 1) : 0.5));
  canvas.frame(barX, mapY, barW, barH, kFrame);
  for (const Tick& t : ticks) {
    const int y = range > 0 ? mapY + int(std::lround((zmax - t.value) / range * (barH - 1)))
                            : mapY + barH / 2;
    canvas.fill(barX + barW, y, 5, 1, kInk);
    const int top = std::clamp(y - textH / 2, 0, height - textH);
    canvas.text(labelX, top, t.label, s, kInk);
  }

  // Scale bar under the map with end ticks.
  canvas.fill(mapX, scaleY + textH / 2 - 2, scalePx, 4, kInk);
  canvas.fill(mapX, scaleY, 2, textH, kInk);
  canvas.fill(mapX + scalePx - 2, scaleY, 2, textH, kInk);
  canvas.text(mapX + scalePx + 10, scaleY, scaleLabel, s, kInk);

  writePng(canvas, path, options.title);
}

}  // namespace scallop
