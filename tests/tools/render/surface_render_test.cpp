// The ray-traced 3-D picture (tools/render/surface_render.h, surface_scene.h,
// height_surface.h) against closed forms: seen from straight above (orthographic) and
// lit from the west at 45 degrees, a block 0.1 mm high casts a shadow 0.1 mm long on
// the floor east of it and none west; a tilted plane's shading factor is Lambert's law
// for its normal, ambient + (1 - ambient) n.l / sin(el); the colour of a pixel is the
// colour map at the height hit there, the bilinear interpolation of the four nodes
// around the hit, which lies on the ray; the exact ray-patch intersection through
// Embree's tiles is the first sign change of the ray's height over the surface found by
// fine marching; marks finer than a pixel average out instead of aliasing; and the
// picture is the same bytes on 1 and 2 threads.
#include "tools/render/surface_render.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "base/constants.h"
#include "tests/support/sampled_field.h"
#include "tools/render/height_colours.h"
#include "tools/render/render_png.h"

namespace scallop {
namespace {

// A renderer of a whole map (k = 1) from a camera on its box.
struct Rig {
  SurfaceGrid surface;
  std::unique_ptr<SurfaceScene> scene;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<SurfaceRenderer> renderer;

  Rig(const ZMap& map, double exaggeration, Direction view, Direction light, int w, int h,
      SurfaceLook look = SurfaceLook())
      : surface(map, wholeMap(map.grid()), 1, "map") {
    surface.setExaggeration(exaggeration, 0);
    const auto [lo, hi] = surface.heightRange();
    const double x0 = surface.nodeX(0), x1 = surface.nodeX(surface.nx() - 1);
    const double y0 = surface.nodeY(0), y1 = surface.nodeY(surface.ny() - 1);
    const double z0 = surface.worldZ(lo) - 0.01, z1 = surface.worldZ(hi);
    camera = std::make_unique<Camera>(
        view, Projection::kOrthographic,
        std::array<Vec3, 8>{Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x0, y1, z0), Vec3(x1, y1, z0),
                            Vec3(x0, y0, z1), Vec3(x1, y0, z1), Vec3(x0, y1, z1), Vec3(x1, y1, z1)},
        w, h);
    scene = std::make_unique<SurfaceScene>(surface);
    look.light = light;
    look.baseZ = z0;
    renderer = std::make_unique<SurfaceRenderer>(*scene, *camera, look);
  }
  // The sample whose ray passes over the map point (x, y) (seen from above).
  SurfaceSample at(double x, double y) const {
    const auto p = camera->pixelOf(Vec3(x, y, 0));
    return renderer->sample(p[0], p[1]);
  }
};

constexpr Direction kAbove{180, 90};

TEST(SurfaceRender, BlockCastsItsHeightLongShadowEastUnderWestLight) {
  // Floor z = 0 and a block 0.1 mm high over x in [0.2, 0.3] mm, on 0.002 mm cells.
  const double s = 0.002, height = 0.1;
  const ZMap map = sampledField(
      0, 0, 300, 60, s, [&](double x, double) { return x >= 0.2 && x <= 0.3 ? height : 0.0; });
  const Rig rig(map, 1, kAbove, {270, 45}, 1200, 240);
  // The block's top edge: its last node on the east, its first on the west.
  double east = 0, west = 1;
  for (int64_t i = 0; i < map.nx(); ++i)
    if (map.at(i, 0) == height) {
      east = std::max(east, map.grid().cellCentreX(i));
      west = std::min(west, map.grid().cellCentreX(i));
    }
  const double y = 0.06;
  double lastShadow = -1;
  for (double x = 0.005; x < 0.595; x += 0.0005) {
    const SurfaceSample a = rig.at(x, y);
    ASSERT_EQ(a.what, SurfaceSample::What::kSurface) << x;
    EXPECT_NEAR(a.point.x, x, 1e-9);
    if (a.heightMm != 0) continue;  // the block and its flanks
    if (x < west) {
      EXPECT_TRUE(a.lit) << "no shadow west of the block, x = " << x;
    }
    if (!a.lit) lastShadow = std::max(lastShadow, x);
    // Light 45 degrees up: the floor's factor is 1 lit and the ambient share shadowed.
    EXPECT_NEAR(a.factor, a.lit ? 1.0 : kRenderAmbient, 1e-12) << x;
  }
  // The shadow reaches 0.1 mm (the block's height / tan 45) from the block's top edge,
  // to the sampling step and the bilinear flank's one cell.
  EXPECT_NEAR(lastShadow - east, height, s);
  // All of the floor between the flank's foot and that reach is in shadow.
  for (double x = east + s + 0.001; x < east + height - 0.001; x += 0.0005)
    EXPECT_FALSE(rig.at(x, y).lit) << x;
}

TEST(SurfaceRender, TiltedPlaneShadeIsLambertsLaw) {
  const double a = 0.3, b = -0.2, e = 2.5;
  const ZMap map =
      sampledField(0, 0, 80, 60, 0.01, [&](double x, double y) { return a * x + b * y; });
  const Vec3 n = normalize(Vec3(-e * a, -e * b, 1));
  for (const Direction light :
       {Direction{100, 30}, Direction{315, 45}, Direction{200, 70}, Direction{90, 10}}) {
    const Rig rig(map, e, kAbove, light, 400, 300);
    const SurfaceSample sm = rig.at(0.41, 0.27);
    ASSERT_EQ(sm.what, SurfaceSample::What::kSurface);
    const double nl = dot(n, towards(light));
    const double expected = kRenderAmbient + (1 - kRenderAmbient) * std::max(0.0, nl) /
                                                 std::sin(light.elevationDeg * kRadPerDeg);
    EXPECT_NEAR(sm.factor, expected, 1e-12) << light.azimuthDeg << " " << light.elevationDeg;
    EXPECT_EQ(sm.lit, nl > 0);
    EXPECT_NEAR(sm.normal.x, n.x, 1e-12);
    EXPECT_NEAR(sm.normal.y, n.y, 1e-12);
  }
}

TEST(SurfaceRender, PixelColourIsTheColourMapAtTheHeightHit) {
  // A bumpy surface seen obliquely: each hit lies on the ray and on the bilinear surface
  // through the four nodes around it, and its colour is the map's at that height.
  const ZMap map = sampledField(0, 0, 60, 50, 0.02, [](double x, double y) {
    return 0.05 * std::sin(7 * x) * std::cos(5 * y) + 0.01 * x;
  });
  SurfaceLook look;
  look.zLow = -0.04, look.zHigh = 0.05;
  look.samplesPerSide = 1;
  const double e = 3;
  const Rig rig(map, e, {210, 35}, {315, 45}, 160, 120, look);
  const TracedImage image = rig.renderer->trace(160, 120);
  const double flat = std::sin(45 * kRadPerDeg);
  const double maxFactor = kRenderAmbient + (1 - kRenderAmbient) / flat;
  const GridSpec& g = map.grid();
  int checked = 0;
  for (int r = 0; r < 120; r += 7)
    for (int c = 0; c < 160; c += 5) {
      const SurfaceSample sm = rig.renderer->sample(c + 0.5, r + 0.5);
      if (sm.what != SurfaceSample::What::kSurface) continue;
      // The bilinear height at the hit, from the nodes.
      const double fx = (sm.point.x - g.cellCentreX(0)) / g.spacing;
      const double fy = (sm.point.y - g.cellCentreY(0)) / g.spacing;
      const int64_t i = std::min<int64_t>(int64_t(fx), g.nx - 2);
      const int64_t j = std::min<int64_t>(int64_t(fy), g.ny - 2);
      const double u = fx - double(i), v = fy - double(j);
      const double h = map.at(i, j) * (1 - u) * (1 - v) + map.at(i + 1, j) * u * (1 - v) +
                       map.at(i, j + 1) * (1 - u) * v + map.at(i + 1, j + 1) * u * v;
      EXPECT_NEAR(sm.heightMm, h, 1e-9);
      EXPECT_NEAR(sm.point.z, e * h, 1e-9);  // the hit is on the surface
      const png::Rgb want =
          shaded(viridis((h - look.zLow) / (look.zHigh - look.zLow)), sm.factor, maxFactor);
      const uint8_t* p = &image.rgb[(size_t(r) * 160 + size_t(c)) * 3];
      EXPECT_EQ(p[0], want.r);
      EXPECT_EQ(p[1], want.g);
      EXPECT_EQ(p[2], want.b);
      ++checked;
    }
  EXPECT_GT(checked, 200);
}

// The height of the ray over the bilinear surface, by fine marching and bisection: the
// first t where it changes sign (an independent reference for the exact intersection).
double marchedHit(const SurfaceGrid& s, const Vec3& o, const Vec3& d, double tMax) {
  auto over = [&](double t) {
    const Vec3 p = o + d * t;
    const double fx = (p.x - s.nodeX(0)) / s.step(), fy = (p.y - s.nodeY(0)) / s.step();
    if (fx < 0 || fy < 0 || fx > double(s.nx() - 1) || fy > double(s.ny() - 1)) return double(NAN);
    const int64_t i = std::min<int64_t>(int64_t(fx), s.nx() - 2);
    const int64_t j = std::min<int64_t>(int64_t(fy), s.ny() - 2);
    const double u = fx - double(i), v = fy - double(j);
    const double h = s.height(i, j) * (1 - u) * (1 - v) + s.height(i + 1, j) * u * (1 - v) +
                     s.height(i, j + 1) * (1 - u) * v + s.height(i + 1, j + 1) * u * v;
    return p.z - s.worldZ(h);
  };
  const int steps = 200000;
  double prevT = 0, prev = over(0);
  for (int k = 1; k <= steps; ++k) {
    const double t = tMax * k / steps, f = over(t);
    if (!std::isnan(prev) && !std::isnan(f) && (prev > 0) != (f > 0)) {
      double lo = prevT, hi = t;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((over(mid) > 0) == (prev > 0) ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    prevT = t, prev = f;
  }
  return HUGE_VAL;
}

TEST(SurfaceScene, FirstHitIsTheMarchedOne) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  const ZMap map = sampledField(0, 0, 70, 45, 0.1, [&](double x, double y) {
    return 0.4 * std::sin(1.3 * x + 0.7 * y) + 0.2 * std::cos(2.1 * y) + 0.05 * unit(rng);
  });
  SurfaceGrid surface(map, wholeMap(map.grid()), 1, "map");
  surface.setExaggeration(1.7, 0.1);
  const SurfaceScene scene(surface);
  int hits = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 o(7 * unit(rng), 4.5 * unit(rng), 2 + unit(rng));
    const Vec3 d = normalize(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, -0.2 - unit(rng)));
    const PatchHit h = scene.intersect(o, d, 0, HUGE_VAL);
    const double marched = marchedHit(surface, o, d, 20);
    if (marched == HUGE_VAL) {
      EXPECT_FALSE(h.found()) << k;
      continue;
    }
    ASSERT_TRUE(h.found()) << k;
    EXPECT_NEAR(h.t, marched, 1e-6) << k;
    ++hits;
    // The ray is occluded before the hit and not in front of it.
    EXPECT_TRUE(scene.occluded(o, d, 0, h.t + 1e-6));
    EXPECT_FALSE(scene.occluded(o, d, 0, h.t - 1e-6));
  }
  EXPECT_GT(hits, 150);
}

TEST(SurfaceScene, CellsWithoutHeightLeaveAHole) {
  // Plane z = 0 with one NaN cell: the four patches around its node are left out, so a
  // vertical ray through the cell's centre meets nothing.
  ZMap map = sampledField(0, 0, 20, 20, 0.1, [](double, double) { return 0.0; });
  map.at(10, 10) = NAN;
  SurfaceGrid surface(map, wholeMap(map.grid()), 1, "map");
  const SurfaceScene scene(surface);
  const double cx = map.grid().cellCentreX(10), cy = map.grid().cellCentreY(10);
  EXPECT_FALSE(scene.intersect(Vec3(cx + 0.03, cy - 0.05, 1), Vec3(0, 0, -1), 0, HUGE_VAL).found());
  EXPECT_TRUE(scene.intersect(Vec3(cx + 0.13, cy, 1), Vec3(0, 0, -1), 0, HUGE_VAL).found());
}

TEST(RenderPicture, MarksFinerThanAPixelAverageOut) {
  // Marks of period 0.37 px, 20 um peak to valley (seen from above, grey, light straight
  // above so that mostly the colour shows): the smoothed level of block means leaves a
  // ripple of a few grey levels across the picture, where point sampling would alias
  // them into bands spanning the whole grey range (195 levels).
  const double period = 0.0037;  // mm; the picture is about 0.01 mm a pixel
  const ZMap map = sampledField(0, 0, 4000, 400, 0.001, [&](double x, double) {
    return 0.01 * std::sin(2 * kPi * x / period);
  });
  RenderOptions o;
  o.widthPx = 600, o.heightPx = 200;
  o.view = {180, 90};
  o.light = {0, 90};
  o.exaggeration = 1;
  o.colourMap = ColourMap::kGrey;
  const RenderedPicture p = renderPicture(map, wholeMap(map.grid()), o);
  EXPECT_GT(p.summary.blockCells, 4);
  // The grey along the middle row of the plot, over its middle half.
  const png::Canvas& c = p.canvas;
  int lo = 255, hi = 0, counted = 0;
  const int row = c.height() / 2;
  for (int x = c.width() / 4; x < c.width() / 2; ++x) {
    const uint8_t* px = c.data() + (size_t(row) * size_t(c.width()) + size_t(x)) * 3;
    if (px[0] == 255) continue;  // background
    lo = std::min<int>(lo, px[0]), hi = std::max<int>(hi, px[0]), ++counted;
  }
  EXPECT_GT(counted, 50);
  EXPECT_LE(hi - lo, 3) << "point sampling would span about 195 grey levels";
}

TEST(RenderPicture, SameBytesOnOneAndTwoThreads) {
  const ZMap map = sampledField(0, 0, 300, 200, 0.01, [](double x, double y) {
    return 0.02 * std::sin(9 * x) * std::sin(4 * y) + (x > 1 && x < 1.3 ? 0.03 : 0.0);
  });
  RenderOptions o;
  o.widthPx = 320, o.heightPx = 200;
  std::vector<uint8_t> bytes[2];
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    const RenderedPicture p = renderPicture(map, wholeMap(map.grid()), o);
    const png::Canvas& c = p.canvas;
    bytes[threads - 1].assign(c.data(), c.data() + size_t(c.width()) * size_t(c.height()) * 3);
  }
  EXPECT_TRUE(bytes[0] == bytes[1]);
}

}  // namespace
}  // namespace scallop
