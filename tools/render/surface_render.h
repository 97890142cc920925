// The traced part of a 3-D picture of a height map (`scallop render`, tools/render/
// render_png.h): every pixel of the plot area is the mean colour of a fixed n x n grid of
// samples in it, each sample the surface (tools/render/surface_scene.h) or one of the
// four walls that drop from its edges to a base, seen along the camera's ray.
//
// A sample's colour: the colour map at the height hit there (the bilinear surface's
// height, mm; between zLow and zHigh; cells at or above `uncutHeight` grey), times the
// shading factor
//   f = ambient + (1 - ambient) * lit * max(0, n . l) / sin(light elevation),
// n the surface's unit normal in the exaggerated frame (turned towards the camera),
// l the unit vector towards the light, lit 0 when the shadow ray from the point
// towards the light meets the surface and 1 otherwise; f = 1 on a flat floor in the
// light, as in preview.png; f above 1 blends towards white (tools/render/
// height_colours.h, shaded). Walls are a neutral grey, shaded alike. Where no sample of a
// pixel meets anything the pixel is the background. Deterministic: a pixel is a
// function of its samples alone, whichever thread traces it.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "tools/render/colour_map.h"
#include "tools/render/png_canvas.h"
#include "tools/render/render_camera.h"
#include "tools/render/surface_scene.h"

namespace scallop {

// Shading factor of a shadowed point, and of a flat floor's light share below 1: the
// same ambient light as preview.png.
constexpr double kRenderAmbient = 0.45;

struct SurfaceLook {
  Direction light{315, 45};
  ColourMap colourMap = ColourMap::kViridis;
  double zLow = 0, zHigh = 1;  // the colour range, mm
  double uncutHeight = NAN;    // heights at or above it are grey (NaN: none)
  double baseZ = 0;            // world z of the walls' foot
  int samplesPerSide = 2;      // n: n x n samples a pixel
};

// One sample: what the ray met and how it is drawn.
struct SurfaceSample {
  enum class What { kNothing, kSurface, kWall } what = What::kNothing;
  double t = HUGE_VAL;    // along the ray
  Vec3 point;             // world
  double heightMm = NAN;  // of the surface hit (kSurface)
  Vec3 normal;            // world, unit, towards the camera
  bool lit = false;       // the shadow ray reached the light
  double factor = 0;      // shading factor
  png::Rgb colour{255, 255, 255};
};

// The plot area's pixels (RGB, row 0 at the top) and, for what is drawn over them, the
// nearest depth a sample met in each (HUGE_VALF where none met anything).
struct TracedImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  std::vector<float> depth;
};

class SurfaceRenderer {
 public:
  SurfaceRenderer(const SurfaceScene& scene, const Camera& camera, const SurfaceLook& look);

  // The sample at (px, py) of the plot area (pixels, as Camera::rayThrough takes them).
  SurfaceSample sample(double px, double py) const;
  // Every pixel of a widthPx x heightPx plot area, rows in parallel. `progress`, if
  // given, is called with the rows done and in all, one call at a time; it may throw to
  // cancel the trace (the exception reaches the caller).
  TracedImage trace(int widthPx, int heightPx,
                    const std::function<void(int64_t, int64_t)>& progress = nullptr) const;

 private:
  // The nearest wall hit before `tMax`, if any, with its outward normal.
  bool wallHit(const Ray& ray, double tMax, double& t, Vec3& normal) const;
  void shade(SurfaceSample& s, png::Rgb base) const;

  const SurfaceScene& scene_;
  const SurfaceGrid& surface_;
  Camera camera_;
  SurfaceLook look_;
  Vec3 toLight_;
  double flat_ = 1, maxFactor_ = 1, shadowEpsilon_ = 0;
};

}  // namespace scallop
