#include "tools/render/deviation_view_png.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/constants.h"
#include "tools/render/diverging_colours.h"

namespace scallop {

namespace {

constexpr png::Rgb kNoValue{160, 160, 160};
constexpr int kScale = 2, kPad = 16;

png::Rgb shaded(png::Rgb c, double light) {
  auto f = [light](uint8_t v) { return uint8_t(std::lround(std::clamp(v * light, 0.0, 255.0))); };
  return {f(c.r), f(c.g), f(c.b)};
}

}  // namespace

std::pair<int, int> DeviationViewImage::pixelOf(const Vec3& p) const {
  return {int(std::floor(originX + dot(p, right) * pxPerMm)),
          int(std::floor(originY - dot(p, up) * pxPerMm))};
}

DeviationViewImage renderDeviationView(const TriangleMesh& design,
                                       const std::vector<double>& deviation,
                                       const DeviationView& view, const std::string& title,
                                       int widthPx) {
  DeviationViewImage image;
  image.limitMm = png::divergingLimit(deviation);
  // --- The view: toward the viewer d, screen right (horizontal) and up ---------------
  const double az = view.azimuthDeg * kRadPerDeg, el = view.elevationDeg * kRadPerDeg;
  const Vec3 d{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  image.right = Vec3{-std::sin(az), std::cos(az), 0};
  image.up = cross(d, image.right);
  // A light above the viewer's right shoulder.
  const Vec3 light = normalize(d + 0.35 * image.up + 0.25 * image.right);

  // --- The picture's frame: the design's projected extent at widthPx ----------------
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (const Vec3& v : design.vertices) {
    x0 = std::min(x0, dot(v, image.right)), x1 = std::max(x1, dot(v, image.right));
    y0 = std::min(y0, dot(v, image.up)), y1 = std::max(y1, dot(v, image.up));
  }
  const double spanX = std::max(x1 - x0, 1e-9), spanY = std::max(y1 - y0, 1e-9);
  const int mapW = std::max(16, widthPx);
  image.pxPerMm = mapW / spanX;
  const int mapH = std::clamp(int(std::ceil(spanY * image.pxPerMm)), 16, 4 * mapW);
  image.pxPerMm = std::min(image.pxPerMm, mapH / spanY);
  const int textH = png::kCapHeightPx * kScale;
  const int mapX = kPad, mapY = kPad + textH + 12;
  image.originX = mapX - x0 * image.pxPerMm;
  image.originY = mapY + y1 * image.pxPerMm;

  const int barH = std::max(mapH, 200), barX = mapX + mapW + 24;
  const std::string angles = fmt::format("view: azimuth {:g}\u00b0, elevation {:g}\u00b0",
                                         view.azimuthDeg, view.elevationDeg);
  const std::string key = "red: below the design; blue: material left; grey: no value";
  const int width =
      std::max({barX + png::divergingBarWidth(image.limitMm, kScale) + kPad,
                2 * kPad + png::textWidth(title, kScale), 2 * kPad + png::textWidth(key, kScale)});
  const int keyY = mapY + barH + 14;
  image.canvas = png::Canvas(width, keyY + 2 * (textH + 6) + kPad);
  png::Canvas& canvas = image.canvas;
  canvas.fill(0, 0, canvas.width(), canvas.height(), png::kBackground);
  canvas.text(kPad, kPad, title, kScale, png::kInk);

  // --- Facets with a depth buffer, a sample at each pixel centre ---------------------
  std::vector<double> depth(size_t(mapW) * size_t(mapH), -HUGE_VAL);
  for (size_t t = 0; t < design.triangles.size(); ++t) {
    const auto c = design.corners(t);
    double sx[3], sy[3], sz[3], w[3];
    bool valued = true;
    for (int k = 0; k < 3; ++k) {
      sx[k] = image.originX + dot(c[k], image.right) * image.pxPerMm;
      sy[k] = image.originY - dot(c[k], image.up) * image.pxPerMm;
      sz[k] = dot(c[k], d);
      w[k] = deviation[design.triangles[t][size_t(k)]];
      valued = valued && !std::isnan(w[k]);
    }
    const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (area == 0) continue;  // seen edge-on
    const double lit = 0.3 + 0.7 * std::fabs(dot(design.normals[t], light));
    const int cx0 = std::max(mapX, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
    const int cx1 = std::min(mapX + mapW - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
    const int cy0 = std::max(mapY, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
    const int cy1 = std::min(mapY + mapH - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
    for (int py = cy0; py <= cy1; ++py)
      for (int px = cx0; px <= cx1; ++px) {
        const double qx = px + 0.5, qy = py + 0.5;
        // Barycentric weights of the pixel centre (inside: all >= 0 for either winding).
        const double b0 = ((sx[1] - qx) * (sy[2] - qy) - (sx[2] - qx) * (sy[1] - qy)) / area;
        const double b1 = ((sx[2] - qx) * (sy[0] - qy) - (sx[0] - qx) * (sy[2] - qy)) / area;
        const double b2 = 1 - b0 - b1;
        if (b0 < 0 || b1 < 0 || b2 < 0) continue;
        const double z = b0 * sz[0] + b1 * sz[1] + b2 * sz[2];
        double& best = depth[size_t(py - mapY) * size_t(mapW) + size_t(px - mapX)];
        if (!(z > best)) continue;  // nearer the viewer wins; ties keep the first facet
        best = z;
        const png::Rgb colour =
            valued ? png::diverging((b0 * w[0] + b1 * w[1] + b2 * w[2]) / image.limitMm) : kNoValue;
        canvas.set(px, py, shaded(colour, lit));
      }
  }
  canvas.frame(mapX, mapY, mapW, mapH, png::kFrame);
  png::drawDivergingBar(canvas, barX, mapY, barH, image.limitMm, kScale);
  canvas.text(kPad, keyY, angles, kScale, png::kInk);
  canvas.text(kPad, keyY + textH + 6, key, kScale, png::kInk);
  return image;
}

double writeDeviationViewPng(const TriangleMesh& design, const std::vector<double>& deviation,
                             const DeviationView& view, const std::string& path,
                             const std::string& title) {
  const DeviationViewImage image = renderDeviationView(design, deviation, view, title);
  png::writePng(image.canvas, path, title);
  return image.limitMm;
}

}  // namespace scallop
