#include "tools/render/deviation_view_png.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "base/constants.h"
#include "tools/render/diverging_colours.h"
#include "tools/render/mesh_scene.h"

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
  const auto q = camera.pixelOf(p);
  return {mapX + int(std::floor(q[0])), mapY + int(std::floor(q[1]))};
}

DeviationViewImage renderDeviationView(const TriangleMesh& design,
                                       const std::vector<double>& deviation,
                                       const DeviationView& view, const std::string& title,
                                       int widthPx) {
  DeviationViewImage image;
  image.limitMm = png::divergingLimit(deviation);
  // --- The view in the height pictures' convention (azimuth clockwise from +y) --------
  const Direction camera{90 - view.azimuthDeg, view.elevationDeg};
  const Vec3 toViewer = towards(camera);
  const double az = camera.azimuthDeg * kRadPerDeg;
  const Vec3 right(-std::cos(az), std::sin(az), 0), up = cross(right, -toViewer);
  // The light: given, or above the viewer's right shoulder.
  const Vec3 light = std::isnan(view.light.azimuthDeg)
                         ? normalize(toViewer + 0.35 * up + 0.25 * right)
                         : towards(view.light);

  // --- The picture's frame: the design's box, its aspect as seen ----------------------
  Vec3 lo = design.vertices.empty() ? Vec3() : design.vertices[0], hi = lo;
  for (const Vec3& v : design.vertices) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const std::array<Vec3, 8> corners = {Vec3(lo.x, lo.y, lo.z), Vec3(hi.x, lo.y, lo.z),
                                       Vec3(lo.x, hi.y, lo.z), Vec3(hi.x, hi.y, lo.z),
                                       Vec3(lo.x, lo.y, hi.z), Vec3(hi.x, lo.y, hi.z),
                                       Vec3(lo.x, hi.y, hi.z), Vec3(hi.x, hi.y, hi.z)};
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (const Vec3& v : design.vertices) {
    x0 = std::min(x0, dot(v, right)), x1 = std::max(x1, dot(v, right));
    y0 = std::min(y0, dot(v, up)), y1 = std::max(y1, dot(v, up));
  }
  const double spanX = std::max(x1 - x0, 1e-9), spanY = std::max(y1 - y0, 1e-9);
  const int mapW = std::max(16, widthPx);
  const int mapH = std::clamp(int(std::ceil(spanY * mapW / spanX)), 16, 4 * mapW);
  image.camera = Camera(camera, view.projection, corners, mapW, mapH);
  const int textH = png::kCapHeightPx * kScale;
  image.mapX = kPad, image.mapY = kPad + textH + 12;
  const int mapX = image.mapX, mapY = image.mapY;

  const int barH = std::max(mapH, 200), barX = mapX + mapW + 24;
  const std::string angles = fmt::format(
      "view: azimuth {:g}\u00b0, elevation {:g}\u00b0{}; light {}, with shadows", view.azimuthDeg,
      view.elevationDeg, view.projection == Projection::kPerspective ? ", perspective" : "",
      std::isnan(view.light.azimuthDeg)
          ? std::string("above the viewer's right shoulder")
          : fmt::format("from {:g}\u00b0 (clockwise from +y) at {:g}\u00b0", view.light.azimuthDeg,
                        view.light.elevationDeg));
  const std::string key = "red: below the design; blue: material left; grey: no value";
  const int width =
      std::max({barX + png::divergingBarWidth(image.limitMm, kScale) + kPad,
                2 * kPad + png::textWidth(title, kScale), 2 * kPad + png::textWidth(key, kScale),
                2 * kPad + png::textWidth(angles, kScale)});
  const int keyY = mapY + barH + 14;
  image.canvas = png::Canvas(width, keyY + 2 * (textH + 6) + kPad);
  png::Canvas& canvas = image.canvas;
  canvas.fill(0, 0, canvas.width(), canvas.height(), png::kBackground);
  canvas.text(kPad, kPad, title, kScale, png::kInk);

  // --- Rays: a fixed 2 x 2 grid of samples a pixel, each with its shadow ray ---------
  const MeshScene scene(design);
  const double size = std::max(length(hi - lo), 1e-9);
  const Camera& cam = image.camera;
  auto sample = [&](double px, double py) -> png::Rgb {
    const Ray ray = cam.rayThrough(px, py);
    const MeshHit h = scene.intersect(ray.origin, ray.direction, 0, HUGE_VAL);
    if (!h.found()) return png::kBackground;
    const auto& tri = design.triangles[size_t(h.triangle)];
    const double w[3] = {deviation[tri[0]], deviation[tri[1]], deviation[tri[2]]};
    const double b0 = 1 - h.b1 - h.b2;
    const bool valued = !std::isnan(w[0] + w[1] + w[2]);
    const png::Rgb colour =
        valued ? png::diverging((b0 * w[0] + h.b1 * w[1] + h.b2 * w[2]) / image.limitMm) : kNoValue;
    Vec3 n = design.normals[size_t(h.triangle)];
    if (dot(n, ray.direction) > 0) n = -n;
    const double lambert = std::max(0.0, dot(n, light));
    const Vec3 p = ray.origin + ray.direction * h.t;
    const bool lit = lambert > 0 && !scene.occluded(p, light, 1e-6 * size, HUGE_VAL);
    return shaded(colour, 0.3 + 0.7 * (lit ? lambert : 0.0));
  };
  std::vector<uint8_t> rgb(size_t(mapW) * size_t(mapH) * 3);
  tbb::parallel_for(tbb::blocked_range<int>(0, mapH), [&](const tbb::blocked_range<int>& rows) {
    for (int r = rows.begin(); r < rows.end(); ++r)
      for (int c = 0; c < mapW; ++c) {
        int sum[3] = {0, 0, 0};
        for (int b = 0; b < 2; ++b)
          for (int a = 0; a < 2; ++a) {
            const png::Rgb s = sample(c + 0.25 + 0.5 * a, r + 0.25 + 0.5 * b);
            sum[0] += s.r, sum[1] += s.g, sum[2] += s.b;
          }
        for (int k = 0; k < 3; ++k)
          rgb[(size_t(r) * size_t(mapW) + size_t(c)) * 3 + size_t(k)] = uint8_t((sum[k] + 2) / 4);
      }
  });
  for (int r = 0; r < mapH; ++r)
    for (int c = 0; c < mapW; ++c) {
      const uint8_t* p = &rgb[(size_t(r) * size_t(mapW) + size_t(c)) * 3];
      canvas.set(mapX + c, mapY + r, {p[0], p[1], p[2]});
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
