#include "tools/render/deviation_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tools/render/png_canvas.h"

namespace scallop {

namespace {

using png::Canvas;
using png::Rgb;

constexpr Rgb kNoDesign{160, 160, 160};

// ColorBrewer RdBu (colour-blind safe): red at t = -1 (below the design), white at 0,
// blue at t = +1 (material left); linear between the five stops.
Rgb diverging(double t) {
  static constexpr Rgb kStops[] = {
      {178, 24, 43}, {244, 165, 130}, {247, 247, 247}, {146, 197, 222}, {33, 102, 172}};
  t = std::clamp(t, -1.0, 1.0);
  const double x = (t + 1) * 2;  // 0 .. 4
  const int k = std::min(3, int(x));
  const double f = x - k;
  auto mix = [f](uint8_t a, uint8_t b) { return uint8_t(std::lround(a + (b - a) * f)); };
  return {mix(kStops[k].r, kStops[k + 1].r), mix(kStops[k].g, kStops[k + 1].g),
          mix(kStops[k].b, kStops[k + 1].b)};
}

// Smallest 1, 2 or 5 x 10^k that is >= x (x > 0).
double niceAbove(double x) {
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= x * (1 - 1e-12)) return m * mag;
  return 10 * mag;
}

double colourLimit(const std::vector<double>& deviation) {
  std::vector<double> mags;
  for (double d : deviation)
    if (!std::isnan(d)) mags.push_back(std::fabs(d));
  if (mags.empty()) return 1e-3;
  auto q = mags.begin() + long(double(mags.size() - 1) * 0.99);
  std::nth_element(mags.begin(), q, mags.end());
  return niceAbove(std::max(*q, 1e-6));  // at least 1 nm so the scale is defined
}

}  // namespace

double writeDeviationPng(const DesignComparison& c, const std::string& path,
                         const std::string& title, int maxPixels) {
  const GridSpec& g = c.grid;
  if (g.nx <= 0 || g.ny <= 0) throw InputError(path, "cannot draw an empty map");
  const double limit = colourLimit(c.deviation);
  maxPixels = std::max(16, maxPixels);
  const int64_t k = (std::max(g.nx, g.ny) + maxPixels - 1) / maxPixels;
  const int w = int((g.nx + k - 1) / k), h = int((g.ny + k - 1) / k);
  // Per block: the deepest over-cut beyond the tolerance, else the largest value.
  std::vector<double> low(size_t(w) * size_t(h), HUGE_VAL), high(low.size(), -HUGE_VAL);
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double d = c.deviation[size_t(j * g.nx + i)];
      if (std::isnan(d)) continue;
      const size_t p = size_t(h - 1 - j / k) * size_t(w) + size_t(i / k);  // north up
      low[p] = std::min(low[p], d), high[p] = std::max(high[p], d);
    }
  const int up = std::max(
      1, std::min((400 + std::max(w, h) - 1) / std::max(w, h), maxPixels / std::max(w, h)));

  constexpr int s = 2, pad = 16, barW = 24;
  const int textH = png::kCapHeightPx * s;
  const std::string& heading = title;
  const int mapW = w * up, mapH = h * up;
  const int mapX = pad, mapY = pad + textH + 12;
  const int barH = std::max(mapH, 200), barX = mapX + mapW + 24, labelX = barX + barW + 10;
  const bool micro = limit < 0.5;
  const double unitPerMm = micro ? 1000.0 : 1.0;
  const std::string unit = micro ? "\u00b5m" : "mm";
  const int decimals = std::max(0, -int(std::floor(std::log10(limit * unitPerMm / 2) + 1e-9)));
  std::vector<std::pair<double, std::string>> ticks;
  for (int t = 2; t >= -2; --t) {
    const double v = limit * t / 2;
    ticks.push_back({v, (v > 0 ? "+" : "") + png::formatValue(v * unitPerMm, decimals, unit)});
  }
  int labelW = 0;
  for (const auto& t : ticks) labelW = std::max(labelW, png::textWidth(t.second, s));
  const std::string key1 = "blue: material left (machined above design)";
  const std::string key2 =
      fmt::format("red: below design; o: gouge deeper than {:g} {}", c.tolerance * unitPerMm, unit);
  const std::string key3 = "grey: no design surface";
  const int keyY = mapY + barH + 14;
  const int width =
      std::max({labelX + labelW + pad, pad + png::textWidth(heading, s) + pad,
                pad + png::textWidth(key1, s) + pad, pad + png::textWidth(key2, s) + pad});
  const int height = keyY + 3 * (textH + 6) + pad;
  Canvas canvas(width, height);
  canvas.fill(0, 0, width, height, png::kBackground);
  canvas.text(pad, pad, heading, s, png::kInk);

  for (int r = 0; r < h; ++r)
    for (int a = 0; a < w; ++a) {
      const size_t p = size_t(r) * size_t(w) + size_t(a);
      Rgb colour = kNoDesign;
      if (low[p] != HUGE_VAL)
        colour = diverging((low[p] < -c.tolerance ? low[p] : high[p]) / limit);
      canvas.fill(mapX + a * up, mapY + r * up, up, up, colour);
    }
  canvas.frame(mapX, mapY, mapW, mapH, png::kFrame);
  // Rings around the deepest cell of each gouge (the 200 deepest).
  for (size_t n = 0; n < std::min<size_t>(c.gouges.size(), 200); ++n) {
    const Gouge& gouge = c.gouges[n];
    const int cx = mapX + int(gouge.i / k) * up + up / 2;
    const int cy = mapY + (h - 1 - int(gouge.j / k)) * up + up / 2;
    for (int deg = 0; deg < 360; deg += 10) {
      const double a = deg * kRadPerDeg;
      canvas.fill(cx + int(std::lround(6 * std::cos(a))), cy + int(std::lround(6 * std::sin(a))), 2,
                  2, png::kInk);
    }
  }

  for (int y = 0; y < barH; ++y)
    canvas.fill(barX, mapY + y, barW, 1, diverging(1.0 - 2.0 * y / (barH - 1)));
  canvas.frame(barX, mapY, barW, barH, png::kFrame);
  for (const auto& t : ticks) {
    const int y = mapY + int(std::lround((limit - t.first) / (2 * limit) * (barH - 1)));
    canvas.fill(barX + barW, y, 5, 1, png::kInk);
    canvas.text(labelX, std::clamp(y - textH / 2, 0, height - textH), t.second, s, png::kInk);
  }
  canvas.text(pad, keyY, key1, s, png::kInk);
  canvas.text(pad, keyY + textH + 6, key2, s, png::kInk);
  canvas.text(pad, keyY + 2 * (textH + 6), key3, s, png::kInk);
  png::writePng(canvas, path, title);
  return limit;
}

}  // namespace scallop
