// The 3-D picture: level and exaggeration, camera, tracing, and the layout around the
// traced plot (render_png.h).
#include "tools/render/render_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "base/input_error.h"
#include "tools/render/colour_bar.h"
#include "tools/render/height_colours.h"
#include "tools/render/height_surface.h"
#include "tools/render/relief_shading.h"
#include "tools/render/render_box.h"
#include "tools/render/surface_render.h"
#include "tools/render/surface_scene.h"

namespace scallop {

namespace {

constexpr int kMaxPicturePx = 16384;
// The automatic exaggeration makes the relief (the colour range) this share of the
// region's longer side.
constexpr double kReliefShare = 0.2;
// ... unless all the heights would then stand taller than this share of it.
constexpr double kTallestShare = 0.6;
// The base lies this share of the region's longer side below the lowest height.
constexpr double kBaseDepthShare = 0.03;
// The colour range is taken on the region sampled to at most this many cells a side.
constexpr int64_t kRangeSamples = 1024;

double twoSignificant(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return std::round(x / unit) * unit;
}

// The colour range of the region: robustRange (preview.png's) of the region sampled
// every q cells, cells without a height taking the highest height (left out as "uncut");
// and the sample's lowest and highest heights.
struct SampledRange {
  double low = NAN, high = NAN, lowest = NAN, highest = NAN;
};

SampledRange sampledRange(const ZMap& map, const CellRegion& region, double uncutHeight) {
  const int64_t w = region.i1 - region.i0, h = region.j1 - region.j0;
  const int64_t q = std::max<int64_t>(1, (std::max(w, h) + kRangeSamples - 1) / kRangeSamples);
  HeightRaster raster;
  raster.w = int((w + q - 1) / q), raster.h = int((h + q - 1) / q);
  raster.cellMm = double(q) * map.grid().spacing;
  SampledRange out;
  double lowest = HUGE_VAL, highest = -HUGE_VAL;
  for (int r = 0; r < raster.h; ++r)
    for (int a = 0; a < raster.w; ++a) {
      const double z = map.at(region.i0 + a * q, region.j1 - 1 - r * q);
      raster.z.push_back(z);
      if (!std::isnan(z)) lowest = std::min(lowest, z), highest = std::max(highest, z);
    }
  if (highest == -HUGE_VAL) return out;
  for (double& z : raster.z)
    if (std::isnan(z)) z = highest;
  std::tie(out.low, out.high) = robustRange(raster, uncutHeight);
  out.lowest = lowest, out.highest = highest;
  return out;
}

std::array<Vec3, 8> boxCorners(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x0, y1, z0), Vec3(x1, y1, z0),
          Vec3(x0, y0, z1), Vec3(x1, y0, z1), Vec3(x0, y1, z1), Vec3(x1, y1, z1)};
}

std::string degrees(double v) {
  return fmt::format("{:g}\u00b0", v);
}

}  // namespace

void checkRenderOptions(const RenderOptions& o, const RenderOptionNames& names) {
  for (int px : {o.widthPx, o.heightPx})
    if (px < 1 || px > kMaxPicturePx)
      throw InputError(names.size, fmt::format("expected a width and a height in [1, {}] pixels, "
                                               "got {} x {}",
                                               kMaxPicturePx, o.widthPx, o.heightPx));
  auto direction = [](const Direction& d, const std::string& name) {
    if (!std::isfinite(d.azimuthDeg) || !std::isfinite(d.elevationDeg))
      throw InputError(name, "expected finite angles AZ EL in degrees");
    if (!(d.elevationDeg > 0 && d.elevationDeg <= 90))
      throw InputError(
          name, fmt::format("expected an elevation in (0, 90] degrees, got {:g}", d.elevationDeg));
  };
  direction(o.view, names.view);
  direction(o.light, names.light);
  if (!std::isnan(o.exaggeration) && !(o.exaggeration > 0 && o.exaggeration <= 1e6))
    throw InputError(names.exaggeration,
                     fmt::format("expected a factor in (0, 1e6], got {:g}", o.exaggeration));
}

RenderedPicture renderPicture(const ZMap& map, const CellRegion& region,
                              const RenderOptions& options, const char* regionName) {
  checkRenderOptions(options);
  const GridSpec& g = map.grid();
  RenderedPicture out;
  RenderSummary& sum = out.summary;

  // Colour range and exaggeration, from the region sampled.
  const SampledRange range = sampledRange(map, region, options.uncutHeight);
  const double zLow = range.low, zHigh = range.high;
  if (std::isnan(zLow)) throw InputError(regionName, "holds no height (every cell is NaN)");
  sum.zLow = zLow, sum.zHigh = zHigh;
  const double x0 = g.cellCentreX(region.i0), x1 = g.cellCentreX(region.i1 - 1);
  const double y0 = g.cellCentreY(region.j0), y1 = g.cellCentreY(region.j1 - 1);
  const double side = std::max(x1 - x0, y1 - y0);
  sum.automaticExaggeration = std::isnan(options.exaggeration);
  if (!sum.automaticExaggeration) {
    sum.exaggeration = options.exaggeration;
  } else if (zHigh > zLow) {
    // The colour range a fifth of the side, and all the heights at most kTallestShare
    // of it (a stock edge left standing beside fine scallops).
    double e = kReliefShare * side / (zHigh - zLow);
    if (range.highest > range.lowest)
      e = std::min(e, kTallestShare * side / (range.highest - range.lowest));
    sum.exaggeration = twoSignificant(e);
  }
  const double e = sum.exaggeration;

  // Layout, px: title above, notes below, the colour bar on the right, the plot with a
  // margin for the box's labels.
  const int W = options.widthPx, H = options.heightPx;
  const int s = W >= 1200 && H >= 700 ? 2 : 1;
  const int pad = 8 * s, textH = png::kCapHeightPx * s, lineH = textH + 6 * s;
  const int titleH = options.title.empty() ? 0 : textH + 8 * s;
  const int notesH = 2 * lineH;
  const int barPx = std::max(1, int(0.6 * (H - titleH - notesH - 2 * pad)));
  const int barPanel = colourBarWidth(zLow, zHigh, barPx, s) + 3 * pad;
  const int plotX = pad, plotY = pad + titleH;
  const int plotW = std::max(1, W - barPanel - 2 * pad),
            plotH = std::max(1, H - plotY - notesH - pad);
  // The box's labels need about four text heights; a small picture gives them less.
  const int margin = std::min({4 * textH + 14 * s, plotW / 6, plotH / 6});
  const int camW = std::max(1, plotW - 2 * margin), camH = std::max(1, plotH - 2 * margin);

  // A first camera on the sampled range picks the level: nodes about a pixel apart
  // where the picture is finest.
  const double depth = kBaseDepthShare * side;
  const Camera first(options.view, options.projection,
                     boxCorners(x0, y0, -depth, x1, y1, e * (zHigh - zLow)), camW, camH);
  double footprint = HUGE_VAL;
  for (const Vec3& c : boxCorners(x0, y0, -depth, x1, y1, e * (zHigh - zLow)))
    footprint = std::min(footprint, first.mmPerPxAt(c));
  const int64_t narrow = std::min(region.i1 - region.i0, region.j1 - region.j0);
  const int k = int(std::clamp<double>(std::floor(footprint / g.spacing), 1.0,
                                       double(std::max<int64_t>(1, narrow / 2))));
  SurfaceGrid surface(map, region, k, regionName);
  surface.setExaggeration(e, zLow);
  const auto [lowest, highest] = surface.heightRange();
  if (std::isnan(lowest)) throw InputError(regionName, "holds no height (every cell is NaN)");
  sum.blockCells = k, sum.nodesX = surface.nx(), sum.nodesY = surface.ny();

  // The camera on the level's box, the scene, the trace.
  const double sx0 = surface.nodeX(0), sx1 = surface.nodeX(surface.nx() - 1);
  const double sy0 = surface.nodeY(0), sy1 = surface.nodeY(surface.ny() - 1);
  const double baseZ = surface.worldZ(lowest) - depth;
  const Camera camera(options.view, options.projection,
                      boxCorners(sx0, sy0, baseZ, sx1, sy1, surface.worldZ(highest)), camW, camH);
  const SurfaceScene scene(surface);
  sum.tiles = scene.tiles();
  SurfaceLook look;
  look.light = options.light;
  look.colourMap = options.colourMap;
  look.zLow = zLow, look.zHigh = zHigh;
  look.uncutHeight = options.uncutHeight;
  look.baseZ = baseZ;
  look.samplesPerSide = options.samplesPerSide;
  const TracedImage traced =
      SurfaceRenderer(scene, camera, look).trace(camW, camH, options.progress);

  // The picture around it.
  png::Canvas& canvas = out.canvas = png::Canvas(W, H);
  canvas.fill(0, 0, W, H, png::kBackground);
  const int camX = plotX + margin, camY = plotY + margin;
  for (int r = 0; r < camH; ++r)
    for (int c = 0; c < camW; ++c) {
      const uint8_t* p = &traced.rgb[(size_t(r) * size_t(camW) + size_t(c)) * 3];
      canvas.set(camX + c, camY + r, {p[0], p[1], p[2]});
    }
  // The box on the region's cell edges, a pixel and a half outside the walls at least.
  const double grow = 1.5 * s * camera.mmPerPx();
  const double ex0 = g.originX + double(g.offsetI + region.i0) * g.spacing;
  const double ex1 = g.originX + double(g.offsetI + region.i1) * g.spacing;
  const double ey0 = g.originY + double(g.offsetJ + region.j0) * g.spacing;
  const double ey1 = g.originY + double(g.offsetJ + region.j1) * g.spacing;
  drawRenderBox(canvas, camX, camY, camera, traced,
                {std::min(ex0, sx0 - grow), std::min(ey0, sy0 - grow), std::max(ex1, sx1 + grow),
                 std::max(ey1, sy1 + grow), baseZ},
                s);
  if (!options.title.empty()) canvas.text(pad, pad, options.title, s, png::kInk);
  const int barX = W - barPanel + pad, barY = plotY + (plotH - barPx) / 2;
  canvas.text(barX, std::max(0, barY - textH - 8 * s), "height", s, png::kInk);
  drawColourBar(canvas, barX, barY, barPx, zLow, zHigh, options.colourMap, s);
  const int n = std::max(1, options.samplesPerSide);
  const std::string notes[2] = {
      fmt::format("heights \u00d7 {:g}{}, light from {} at {} with shadows, {} view from {} at {}",
                  e, sum.automaticExaggeration ? " (automatic)" : "",
                  degrees(options.light.azimuthDeg), degrees(options.light.elevationDeg),
                  options.projection == Projection::kOrthographic ? "orthographic" : "perspective",
                  degrees(options.view.azimuthDeg), degrees(options.view.elevationDeg)),
      k == 1 ? fmt::format("surface: bilinear through the cell centres ({:g} mm apart), "
                           "{} \u00d7 {} samples a pixel",
                           surface.step(), n, n)
             : fmt::format("surface: bilinear through means of {} \u00d7 {} cells ({:g} mm apart), "
                           "{} \u00d7 {} samples a pixel",
                           k, k, surface.step(), n, n)};
  for (int l = 0; l < 2; ++l)
    canvas.text(pad, H - pad - notesH + l * lineH + 4 * s, notes[l], s, png::kInk);
  return out;
}

RenderSummary writeRenderPng(const ZMap& map, const CellRegion& region, const std::string& path,
                             const RenderOptions& options, const char* regionName) {
  const RenderedPicture picture = renderPicture(map, region, options, regionName);
  png::writePng(picture.canvas, path, options.title);
  return picture.summary;
}

}  // namespace scallop
