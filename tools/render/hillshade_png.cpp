#include "tools/render/hillshade_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "base/input_error.h"
#include "tools/render/png_canvas.h"
#include "tools/render/preview_png.h"

namespace scallop {

namespace {

using png::Canvas;
using png::kBackground;
using png::kCapHeightPx;
using png::kFrame;
using png::kInk;
using png::Rgb;
using png::textWidth;

void validate(const HillshadeOptions& o, const std::string& field) {
  if (!std::isfinite(o.light.azimuthDeg))
    throw InputError(field + "azimuth",
                     fmt::format("must be a finite angle in degrees, got {}", o.light.azimuthDeg));
  if (!(o.light.elevationDeg > 0 && o.light.elevationDeg <= 90))
    throw InputError(field + "elevation",
                     fmt::format("must be an angle above the horizon, in (0, 90] degrees, got {}",
                                 o.light.elevationDeg));
  // NaN asks for the automatic value; anything else must be a positive factor.
  if (!std::isnan(o.exaggeration) && !(o.exaggeration > 0 && o.exaggeration <= 1e6))
    throw InputError(field + "exaggeration",
                     fmt::format("must be a factor in (0, 1e6], got {}", o.exaggeration));
}

}  // namespace

double writeHillshadePng(const ZMap& map, const std::string& path, const HillshadeOptions& options,
                         const std::string& field) {
  validate(options, field);
  if (options.colour) {
    PreviewOptions preview;
    preview.maxPixels = options.maxPixels;
    preview.minPixels = options.minPixels;
    preview.title = options.title;
    preview.light = options.light;
    preview.exaggeration = options.exaggeration;
    // The preview's rule: automatic exaggeration and texture boost; a given exaggeration
    // is used alone, for everything.
    if (!std::isnan(options.exaggeration)) preview.textureBoost = 1;
    return writePreviewPng(map, path, preview);
  }
  const ReliefGrid relief =
      reliefGridOf(map, path, options.maxPixels, options.minPixels, options.exaggeration);
  const HeightRaster& grid = relief.grid;
  const int up = relief.up;
  const double exaggeration = relief.exaggeration;
  const std::vector<double> shade = lambert(relief.slope, exaggeration, options.light);

  // Layout, px: title, map, scale bar, legend.
  constexpr int s = 2;  // font scale
  constexpr int pad = 16;
  const int textH = kCapHeightPx * s;
  const std::string& title = options.title;
  const int mapW = grid.w * up, mapH = grid.h * up;
  const int mapX = pad, mapY = pad + (title.empty() ? 0 : textH + 12);
  const png::ScaleBar scale = png::scaleBarFor(grid.cellMm / up, mapW);
  const int scaleY = mapY + mapH + 18;
  const std::string legend = reliefLegend(exaggeration, options.light).front();
  const int legendY = scaleY + textH + 14;
  const int width =
      std::max({mapX + mapW + pad, pad + textWidth(title, s) + pad,
                mapX + png::scaleBarWidth(scale, s) + pad, mapX + textWidth(legend, s) + pad});
  const int height = legendY + textH + pad;

  Canvas canvas(width, height);
  canvas.fill(0, 0, width, height, kBackground);
  if (!title.empty()) canvas.text(pad, pad, title, s, kInk);
  for (int r = 0; r < grid.h; ++r)
    for (int a = 0; a < grid.w; ++a) {
      const double v = 255 * shade[size_t(r) * size_t(grid.w) + size_t(a)];
      const uint8_t g = uint8_t(std::clamp(std::lround(v), 0L, 255L));
      canvas.fill(mapX + a * up, mapY + r * up, up, up, Rgb{g, g, g});
    }
  canvas.frame(mapX, mapY, mapW, mapH, kFrame);
  png::drawScaleBar(canvas, mapX, scaleY, scale, s);
  canvas.text(mapX, legendY, legend, s, kInk);
  writePng(canvas, path, title);
  return exaggeration;
}

}  // namespace scallop
