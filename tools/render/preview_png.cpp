// preview.png: a shaded, colour-mapped picture of a ZMap with a colour bar and a
// scale bar. Canvas, font and PNG writing are in tools/render/png_canvas.h.
#include "tools/render/preview_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tools/io/atomic_file.h"
#include "tools/render/colour_bar.h"
#include "tools/render/height_colours.h"
#include "tools/render/map_cells.h"
#include "tools/render/png_canvas.h"
#include "tools/render/relief_shading.h"

namespace scallop {

namespace {

using png::Canvas;
using png::drawScaleBar;
using png::formatValue;
using png::kBackground;
using png::kCapHeightPx;
using png::kFrame;
using png::kInk;
using png::niceBelow;
using png::Rgb;
using png::ScaleBar;
using png::scaleBarFor;
using png::scaleBarWidth;
using png::textWidth;
using png::writePng;

// Shading factor 1 is "as lit as a flat floor": ambient light plus the Lambert term
// relative to a flat floor's, sin(elevation).
constexpr double kAmbient = 0.3;
// The texture box's half side, raster cells: texture finer than 25 cells (a few
// millimetres on screen) is what automaticTextureBoost may exaggerate further.
constexpr int kTextureRadius = 12;


}  // namespace

double writePreviewPng(const ZMap& map, const std::string& path, const PreviewOptions& options) {
  const ReliefGrid relief =
      reliefGridOf(map, path, options.maxPixels, options.minPixels, options.exaggeration);
  const HeightRaster& grid = relief.grid;
  const Slopes& slope = relief.slope;
  const int up = relief.up;
  const double exaggeration = relief.exaggeration;
  double boost = options.textureBoost;
  std::vector<double> light;
  if (boost == 1) {
    light = lambert(slope, exaggeration, options.light);
  } else {
    const Slopes texture = textureSlopes(grid, kTextureRadius);
    if (std::isnan(boost)) boost = automaticTextureBoost(slope, texture, exaggeration);
    light = lambert(boosted(slope, texture, boost), exaggeration, options.light);
  }
  const double flat = std::sin(options.light.elevationDeg * kRadPerDeg);
  const double maxShade = kAmbient + (1 - kAmbient) / flat;
  // What each cell shows; the colour range comes from the cut cells.
  HeightRaster stock;
  if (options.stockHeights) stock = reduceMap(*options.stockHeights, std::max(16, options.maxPixels));
  const std::vector<CellKind> kinds =
      cellKinds(grid, options.uncutHeight, options.stockHeights ? &stock : nullptr);
  HeightRaster cutOnly = grid;
  for (size_t c = 0; c < kinds.size(); ++c)
    if (kinds[c] != CellKind::Cut) cutOnly.z[c] = NAN;
  const auto [cutLow, cutHigh] = robustRange(cutOnly, options.uncutHeight);
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
  const std::vector<ColourBarTick> ticks = colourBarTicks(zmin, zmax, barH, textH + 4);
  int labelW = 0;
  for (const ColourBarTick& t : ticks) labelW = std::max(labelW, textWidth(t.label, s));
  const int labelX = barX + barW + 10;

  const ScaleBar scale = scaleBarFor(grid.cellMm / up, mapW);
  const int scaleY = mapY + barH + 18;
  const std::vector<std::string> shading =
      reliefLegend(exaggeration, options.light, boost, (2 * kTextureRadius + 1) * grid.cellMm);
  const int shadingY = scaleY + textH + 14, lineH = textH + 10;
  const std::vector<CellLegendLine> cellLines = cellLegend(kinds);
  const int swatchTextX = mapX + textH + 8;  // after a swatch of textH x textH
  const int cellsY = shadingY + int(shading.size()) * lineH;

  int width = std::max({labelX + labelW + pad, pad + textWidth(title, s) + pad,
                        mapX + scaleBarWidth(scale, s) + pad});
  for (const std::string& line : shading) width = std::max(width, mapX + textWidth(line, s) + pad);
  for (const CellLegendLine& line : cellLines)
    width = std::max(width, swatchTextX + textWidth(line.text, s) + pad);
  const int lines = int(shading.size() + cellLines.size());
  const int height = shadingY + lines * lineH - 10 + pad;
  Canvas canvas(width, height);
  canvas.fill(0, 0, width, height, kBackground);
  if (!title.empty()) canvas.text(pad, pad, title, s, kInk);

  // The map: each raster cell becomes an up x up square.
  for (int r = 0; r < grid.h; ++r)
    for (int a = 0; a < grid.w; ++a) {
      const size_t c = size_t(r) * size_t(grid.w) + size_t(a);
      const double z = grid.z[c];
      const double factor = kAmbient + (1 - kAmbient) * light[c] / flat;
      Rgb colour = kNoMaterialColour;
      if (kinds[c] == CellKind::NotCut) colour = shaded(kNotCutColour, factor, maxShade);
      if (kinds[c] == CellKind::Cut)
        colour = shaded(viridis(range > 0 ? (z - zmin) / range : 0.5), factor, maxShade);
      canvas.fill(mapX + a * up, mapY + r * up, up, up, colour);
    }
  canvas.frame(mapX, mapY, mapW, mapH, kFrame);

  // Colour bar, high at the top, with ticks and labels.
  for (int y = 0; y < barH; ++y)
    canvas.fill(barX, mapY + y, barW, 1, viridis(range > 0 ? 1.0 - double(y) / (barH - 1) : 0.5));
  canvas.frame(barX, mapY, barW, barH, kFrame);
  for (const ColourBarTick& t : ticks) {
    const int y = range > 0 ? mapY + int(std::lround((zmax - t.valueMm) / range * (barH - 1)))
                            : mapY + barH / 2;
    canvas.fill(barX + barW, y, 5, 1, kInk);
    const int top = std::clamp(y - textH / 2, 0, height - textH);
    canvas.text(labelX, top, t.label, s, kInk);
  }

  // Scale bar under the map, what the shading exaggerates, and the swatches of the
  // cells not cut and without material.
  drawScaleBar(canvas, mapX, scaleY, scale, s);
  for (size_t k = 0; k < shading.size(); ++k)
    canvas.text(mapX, shadingY + int(k) * lineH, shading[k], s, kInk);
  for (size_t k = 0; k < cellLines.size(); ++k) {
    const int y = cellsY + int(k) * lineH;
    canvas.fill(mapX, y, textH, textH, cellLines[k].colour);
    canvas.frame(mapX, y, textH, textH, kFrame);
    canvas.text(swatchTextX, y, cellLines[k].text, s, kInk);
  }

  writePng(canvas, path, options.title);
  return exaggeration;
}

}  // namespace scallop
