#include "tools/render/colour_bar.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

constexpr int kBarWidth = 12;  // px at font scale 1
constexpr int kLabelGap = 5;   // between the tick and its label, px at scale 1

}  // namespace

std::vector<ColourBarTick> colourBarTicks(double zLow, double zHigh, int barPx, int gapPx) {
  const double range = zHigh - zLow;
  const double largest = std::max(std::abs(zLow), std::abs(zHigh));
  const bool micro = range > 0 ? range < 0.5 : largest < 0.5;
  const double unitPerMm = micro ? 1000.0 : 1.0;
  const std::string unit = micro ? "\u00b5m" : "mm";
  if (!(range > 0)) return {{zLow, png::formatValue(zLow * unitPerMm, micro ? 1 : 4, unit)}};
  double step = png::niceBelow(range * unitPerMm / 3);
  const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
  std::vector<ColourBarTick> ticks = {
      {zHigh, png::formatValue(zHigh * unitPerMm, decimals + 1, unit)},
      {zLow, png::formatValue(zLow * unitPerMm, decimals + 1, unit)}};
  const double minGapMm = gapPx * range / std::max(1, barPx - 1);
  step /= unitPerMm;
  for (double v = std::ceil(zLow / step) * step; v < zHigh; v += step) {
    bool fits = true;
    for (const ColourBarTick& t : ticks) fits = fits && std::abs(t.valueMm - v) >= minGapMm;
    if (fits) ticks.push_back({v, png::formatValue(v * unitPerMm, decimals, unit)});
  }
  return ticks;
}

int colourBarWidth(double zLow, double zHigh, int barPx, int scale) {
  int labels = 0;
  for (const ColourBarTick& t : colourBarTicks(zLow, zHigh, barPx, 2 * png::kCapHeightPx * scale))
    labels = std::max(labels, png::textWidth(t.label, scale));
  return (kBarWidth + kLabelGap) * scale + 5 + labels;
}

void drawColourBar(png::Canvas& canvas, int x, int y, int barPx, double zLow, double zHigh,
                   ColourMap map, int scale) {
  const int barW = kBarWidth * scale, textH = png::kCapHeightPx * scale;
  const double range = zHigh - zLow;
  for (int k = 0; k < barPx; ++k)
    canvas.fill(x, y + k, barW, 1, colourAt(map, range > 0 ? 1.0 - double(k) / (barPx - 1) : 0.5));
  canvas.frame(x, y, barW, barPx, png::kFrame);
  for (const ColourBarTick& t : colourBarTicks(zLow, zHigh, barPx, 2 * textH)) {
    const int ty =
        range > 0 ? y + int(std::lround((zHigh - t.valueMm) / range * (barPx - 1))) : y + barPx / 2;
    canvas.fill(x + barW, ty, 5, 1, png::kInk);
    canvas.text(x + barW + 5 + kLabelGap * scale, std::max(0, ty - textH / 2), t.label, scale,
                png::kInk);
  }
}

}  // namespace scallop
