#include "tools/render/diverging_colours.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace scallop::png {

namespace {

constexpr int kBarWidthPx = 24;

// Smallest 1, 2 or 5 x 10^k that is >= x (x > 0).
double niceAbove(double x) {
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= x * (1 - 1e-12)) return m * mag;
  return 10 * mag;
}

// The bar's five ticks, from +limit down, with their labels.
std::vector<std::pair<double, std::string>> ticksOf(double limit) {
  const DeviationUnit unit = deviationUnit(limit);
  const int decimals = std::max(0, -int(std::floor(std::log10(limit * unit.perMm / 2) + 1e-9)));
  std::vector<std::pair<double, std::string>> ticks;
  for (int t = 2; t >= -2; --t) {
    const double v = limit * t / 2;
    ticks.push_back({v, (v > 0 ? "+" : "") + formatValue(v * unit.perMm, decimals, unit.name)});
  }
  return ticks;
}

}  // namespace

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

double divergingLimit(const std::vector<double>& deviation) {
  std::vector<double> mags;
  for (double d : deviation)
    if (!std::isnan(d)) mags.push_back(std::fabs(d));
  if (mags.empty()) return 1e-3;
  auto q = mags.begin() + long(double(mags.size() - 1) * 0.99);
  std::nth_element(mags.begin(), q, mags.end());
  return niceAbove(std::max(*q, 1e-6));  // at least 1 nm so the scale is defined
}

DeviationUnit deviationUnit(double limit) {
  return limit < 0.5 ? DeviationUnit{1000.0, "\u00b5m"} : DeviationUnit{1.0, "mm"};
}

int divergingBarWidth(double limit, int scale) {
  int labelW = 0;
  for (const auto& t : ticksOf(limit)) labelW = std::max(labelW, textWidth(t.second, scale));
  return kBarWidthPx + 10 + labelW;
}

int drawDivergingBar(Canvas& canvas, int x, int y, int height, double limit, int scale) {
  const int textH = kCapHeightPx * scale;
  for (int r = 0; r < height; ++r)
    canvas.fill(x, y + r, kBarWidthPx, 1, diverging(1.0 - 2.0 * r / (height - 1)));
  canvas.frame(x, y, kBarWidthPx, height, kFrame);
  for (const auto& t : ticksOf(limit)) {
    const int ty = y + int(std::lround((limit - t.first) / (2 * limit) * (height - 1)));
    canvas.fill(x + kBarWidthPx, ty, 5, 1, kInk);
    canvas.text(x + kBarWidthPx + 10, std::clamp(ty - textH / 2, 0, canvas.height() - textH),
                t.second, scale, kInk);
  }
  return divergingBarWidth(limit, scale);
}

}  // namespace scallop::png
