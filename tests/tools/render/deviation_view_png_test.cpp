// deviation_view.png (tools/render/deviation_view_png.h): each facet shows the colour of
// its own deviation (red below the design, blue material left, grey without a value),
// the facet nearer the viewer hides the one behind, the background stays white, and a
// point of the design lands on the pixel pixelOf() names; a facet above another casts
// its shadow on it where the light says; the same bits on 1 and 2 threads.
#include "tools/render/deviation_view_png.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <array>
#include <cmath>
#include <vector>

#include "tools/render/diverging_colours.h"

namespace scallop {
namespace {

png::Rgb pixel(const png::Canvas& c, std::pair<int, int> at) {
  const uint8_t* p = c.data() + (size_t(at.second) * size_t(c.width()) + size_t(at.first)) * 3;
  return {p[0], p[1], p[2]};
}

// Two unit squares side by side in z = 0 (x in [0, 1] and [1, 2]), each two facets, and
// a third square at z = 1 over the first half of the second (x in [1, 1.5]).
struct Scene {
  TriangleMesh mesh;
  std::vector<double> deviation;
};
Scene threeSquares(double left, double right, double top) {
  std::vector<std::array<Vec3, 3>> soup;
  auto square = [&](double x0, double x1, double z) {
    soup.push_back({Vec3{x0, 0, z}, Vec3{x1, 0, z}, Vec3{x0, 1, z}});
    soup.push_back({Vec3{x1, 0, z}, Vec3{x1, 1, z}, Vec3{x0, 1, z}});
  };
  square(0, 1, 0), square(1, 2, 0), square(1, 1.5, 1);
  Scene s{meshFromTriangles(soup), {}};
  for (const Vec3& v : s.mesh.vertices)
    s.deviation.push_back(v.z == 1 ? top : v.x < 1 ? left : v.x > 1 ? right : NAN);
  return s;
}

TEST(DeviationView, FacetsShowTheirOwnDeviationAndTheNearerOneWins) {
  // Vertices at x = 1 have no value (NaN): the facets touching them are grey; the others
  // (x = 0 on the left, x = 2 on the right) take the end colours.
  const Scene s = threeSquares(-0.01, 0.01, 0.01);
  DeviationView view;
  view.elevationDeg = 90;  // straight down: the top square hides [1, 1.5] x [0, 1]
  const DeviationViewImage image = renderDeviationView(s.mesh, s.deviation, view, "test", 200);
  EXPECT_DOUBLE_EQ(image.limitMm, 0.01);
  const png::Canvas& c = image.canvas;
  // The top square's facets hold one value: blue, shaded.
  const png::Rgb top = pixel(c, image.pixelOf({1.25, 0.5, 1}));
  EXPECT_GT(top.b, top.r + 60);
  // Under it nothing of the grey facets shows; beside it (x = 1.9, right square's
  // facet with x = 1 vertices) it is grey.
  const png::Rgb grey = pixel(c, image.pixelOf({1.9, 0.95, 0}));
  EXPECT_EQ(grey.r, grey.g);
  EXPECT_EQ(grey.g, grey.b);
  EXPECT_LT(grey.r, 230);  // not the background
  // The background, beyond the design, is white.
  const png::Rgb blank = pixel(c, {c.width() - 2, c.height() / 2});
  EXPECT_EQ(blank.r, 255);
  EXPECT_EQ(blank.b, 255);
  // From below (elevation -90) the lower squares are nearer: the pixel under the top
  // square is the right square's grey facet, not the top's blue.
  view.elevationDeg = -90;
  const DeviationViewImage below = renderDeviationView(s.mesh, s.deviation, view, "test", 200);
  const png::Rgb under = pixel(below.canvas, below.pixelOf({1.2, 0.9, 0}));
  EXPECT_EQ(under.r, under.b);
  EXPECT_LT(under.r, 230);  // not the background
}

TEST(DeviationView, RedBelowTheDesignBlueAboveInAnyView) {
  const Scene s = threeSquares(-0.01, 0.01, 0.01);
  std::vector<double> values = s.deviation;
  for (double& v : values)
    if (std::isnan(v)) v = 0;
  for (const double az : {0.0, 30.0, 200.0}) {
    DeviationView view;
    view.azimuthDeg = az;
    view.elevationDeg = 50;
    const DeviationViewImage image = renderDeviationView(s.mesh, values, view, "test", 300);
    // Near x = 0 the left square is -L: red; near x = 2 the right square is +L: blue.
    const png::Rgb left = pixel(image.canvas, image.pixelOf({0.05, 0.5, 0}));
    const png::Rgb right = pixel(image.canvas, image.pixelOf({1.95, 0.5, 0}));
    EXPECT_GT(left.r, left.b + 60) << az;
    EXPECT_GT(right.b, right.r + 60) << az;
  }
}

TEST(DeviationView, AFacetAboveCastsItsShadow) {
  // Seen from straight above, lit from the east (+x) 45 degrees up: the top square (z = 1
  // over x in [1, 1.5]) shadows the floor over x in [0, 0.5] (one unit west of it), where
  // the grey facets are 0.3 of their grey; beside the shadow they are lit by
  // 0.3 + 0.7 sin 45 degrees.
  const Scene s = threeSquares(-0.01, 0.01, 0.01);
  DeviationView view;
  view.elevationDeg = 90;
  view.light = {90, 45};
  const DeviationViewImage image = renderDeviationView(s.mesh, s.deviation, view, "test", 400);
  const uint8_t grey = 160;
  const png::Rgb shadow = pixel(image.canvas, image.pixelOf({0.25, 0.5, 0}));
  const png::Rgb lit = pixel(image.canvas, image.pixelOf({0.75, 0.5, 0}));
  EXPECT_EQ(shadow.r, std::lround(grey * 0.3));
  EXPECT_EQ(lit.r, std::lround(grey * (0.3 + 0.7 * std::sqrt(0.5))));
  EXPECT_EQ(shadow.r, shadow.b);
}

TEST(DeviationView, SameBitsOnOneAndTwoThreads) {
  const Scene s = threeSquares(-0.01, 0.01, 0.004);
  std::vector<uint8_t> bytes[2];
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    const DeviationViewImage image =
        renderDeviationView(s.mesh, s.deviation, DeviationView(), "t", 300);
    const png::Canvas& c = image.canvas;
    bytes[threads - 1].assign(c.data(), c.data() + size_t(c.width()) * size_t(c.height()) * 3);
  }
  EXPECT_TRUE(bytes[0] == bytes[1]);
}

}  // namespace
}  // namespace scallop
