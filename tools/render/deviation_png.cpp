#include "tools/render/deviation_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tools/render/diverging_colours.h"
#include "tools/render/png_canvas.h"

namespace scallop {

namespace {

using png::Canvas;
using png::diverging;
using png::Rgb;

constexpr Rgb kNoDesign{160, 160, 160};

}  // namespace

double writeDeviationPng(const DesignComparison& c, const std::string& path,
                         const std::string& title, int maxPixels) {
  const GridSpec& g = c.grid;
  if (g.nx <= 0 || g.ny <= 0) throw InputError(path, "cannot draw an empty map");
  const double limit = png::divergingLimit(c.deviation);
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
  const int barH = std::max(mapH, 200), barX = mapX + mapW + 24, labelX = barX + barW;
  const png::DeviationUnit units = png::deviationUnit(limit);
  const double unitPerMm = units.perMm;
  const std::string unit = units.name;
  const int labelW = png::divergingBarWidth(limit, s) - barW;
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

  png::drawDivergingBar(canvas, barX, mapY, barH, limit, s);
  canvas.text(pad, keyY, key1, s, png::kInk);
  canvas.text(pad, keyY + textH + 6, key2, s, png::kInk);
  canvas.text(pad, keyY + 2 * (textH + 6), key3, s, png::kInk);
  png::writePng(canvas, path, title);
  return limit;
}

}  // namespace scallop
