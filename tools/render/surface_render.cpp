// Tracing the plot area of a 3-D picture: samples, walls, shading (surface_render.h).
#include "tools/render/surface_render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "base/constants.h"
#include "tools/render/height_colours.h"

namespace scallop {

namespace {

// The walls and the cells no move reached: neutral greys, apart from the colour maps.
constexpr png::Rgb kWall{200, 200, 200};
constexpr png::Rgb kUncut{185, 185, 185};

}  // namespace

SurfaceRenderer::SurfaceRenderer(const SurfaceScene& scene, const Camera& camera,
                                 const SurfaceLook& look)
    : scene_(scene), surface_(scene.surface()), camera_(camera), look_(look) {
  toLight_ = towards(look.light);
  flat_ = std::sin(look.light.elevationDeg * kRadPerDeg);
  maxFactor_ = kRenderAmbient + (1 - kRenderAmbient) / flat_;
  // Shadow rays start this far from their point (world mm): past the rounding of the
  // point on its own patch, far below a pixel.
  const double size = std::max({std::abs(surface_.nodeX(0)), std::abs(surface_.nodeY(0)),
                                std::abs(surface_.nodeX(surface_.nx() - 1)),
                                std::abs(surface_.nodeY(surface_.ny() - 1)),
                                double(surface_.nx()) * surface_.step()});
  shadowEpsilon_ = 1e-7 * size;
}

bool SurfaceRenderer::wallHit(const Ray& ray, double tMax, double& tOut, Vec3& normal) const {
  const SurfaceGrid& s = surface_;
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  bool found = false;
  tOut = tMax;
  // South, north (along x, at the first and last row of nodes), west, east.
  for (int side = 0; side < 4; ++side) {
    const bool alongX = side < 2;
    const int64_t fixed = side == 0 ? 0 : side == 1 ? s.ny() - 1 : side == 2 ? 0 : s.nx() - 1;
    const Vec3 n = side == 0   ? Vec3(0, -1, 0)
                   : side == 1 ? Vec3(0, 1, 0)
                   : side == 2 ? Vec3(-1, 0, 0)
                               : Vec3(1, 0, 0);
    if (dot(d, n) >= 0) continue;  // seen from inside: behind the surface
    const double plane = alongX ? s.nodeY(fixed) : s.nodeX(fixed);
    const double t = (plane - (alongX ? o.y : o.x)) / (alongX ? d.y : d.x);
    if (!(t > 0 && t < tOut)) continue;
    const Vec3 p = o + d * t;
    const int64_t count = alongX ? s.nx() : s.ny();
    const double f = ((alongX ? p.x : p.y) - (alongX ? s.nodeX(0) : s.nodeY(0))) / s.step();
    if (!(f >= 0 && f <= double(count - 1))) continue;
    const int64_t k = std::min(int64_t(f), count - 2);
    const double a = alongX ? s.height(k, fixed) : s.height(fixed, k);
    const double b = alongX ? s.height(k + 1, fixed) : s.height(fixed, k + 1);
    const double top = s.worldZ(a + (b - a) * (f - double(k)));
    if (std::isnan(top) || p.z > top || p.z < look_.baseZ) continue;
    tOut = t, normal = n, found = true;
  }
  return found;
}

void SurfaceRenderer::shade(SurfaceSample& s, png::Rgb base) const {
  const double lambert = std::max(0.0, dot(s.normal, toLight_));
  s.lit = lambert > 0 && !scene_.occluded(s.point, toLight_, shadowEpsilon_, HUGE_VAL);
  s.factor = kRenderAmbient + (1 - kRenderAmbient) * (s.lit ? lambert : 0.0) / flat_;
  s.colour = shaded(base, s.factor, maxFactor_);
}

SurfaceSample SurfaceRenderer::sample(double px, double py) const {
  const Ray ray = camera_.rayThrough(px, py);
  const PatchHit hit = scene_.intersect(ray.origin, ray.direction, 0, HUGE_VAL);
  SurfaceSample s;
  double tWall;
  Vec3 wallNormal;
  if (wallHit(ray, hit.t, tWall, wallNormal)) {
    s.what = SurfaceSample::What::kWall;
    s.t = tWall;
    s.point = ray.origin + ray.direction * tWall;
    s.normal = wallNormal;
    shade(s, kWall);
    return s;
  }
  if (!hit.found()) return s;
  s.what = SurfaceSample::What::kSurface;
  s.t = hit.t;
  s.point = ray.origin + ray.direction * hit.t;
  s.heightMm = heightAt(surface_, hit);
  s.normal = normalAt(surface_, hit);
  if (dot(s.normal, ray.direction) > 0) s.normal = -s.normal;  // the underside, through a hole
  const double range = look_.zHigh - look_.zLow;
  const bool uncut = s.heightMm >= look_.uncutHeight;  // false for NaN
  shade(s, uncut ? kUncut
                 : colourAt(look_.colourMap, range > 0 ? (s.heightMm - look_.zLow) / range : 0.5));
  return s;
}

TracedImage SurfaceRenderer::trace(int widthPx, int heightPx,
                                   const std::function<void(int64_t, int64_t)>& progress) const {
  std::atomic<int64_t> rowsDone{0};
  std::mutex reporting;
  TracedImage image;
  image.width = widthPx, image.height = heightPx;
  image.rgb.assign(size_t(widthPx) * size_t(heightPx) * 3, 255);
  image.depth.assign(size_t(widthPx) * size_t(heightPx), HUGE_VALF);
  const int n = std::max(1, look_.samplesPerSide);
  tbb::parallel_for(tbb::blocked_range<int>(0, heightPx), [&](const tbb::blocked_range<int>& rows) {
    for (int r = rows.begin(); r < rows.end(); ++r)
      for (int c = 0; c < widthPx; ++c) {
        // The fixed n x n grid of samples in the pixel; misses count as the background.
        int sum[3] = {0, 0, 0};
        float depth = HUGE_VALF;
        for (int b = 0; b < n; ++b)
          for (int a = 0; a < n; ++a) {
            const SurfaceSample s = sample(c + (a + 0.5) / n, r + (b + 0.5) / n);
            sum[0] += s.colour.r, sum[1] += s.colour.g, sum[2] += s.colour.b;
            if (s.what != SurfaceSample::What::kNothing) depth = std::min(depth, float(s.t));
          }
        const size_t at = size_t(r) * size_t(widthPx) + size_t(c);
        for (int k = 0; k < 3; ++k)
          image.rgb[at * 3 + size_t(k)] = uint8_t((sum[k] + n * n / 2) / (n * n));
        image.depth[at] = depth;
      }
    if (progress) {
      const int64_t done = rowsDone += rows.size();
      std::lock_guard<std::mutex> one(reporting);
      progress(done, heightPx);
    }
  });
  return image;
}

}  // namespace scallop
