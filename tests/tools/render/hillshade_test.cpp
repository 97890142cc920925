// Relief shading (tools/render/relief_shading.h) and the hill-shade picture
// (tools/render/hillshade_png.h) against geometry worked out by hand: a facet tilted by
// t towards the light makes the angle 90 - el - t with it, so its Lambert term is
// sin(el + t); turned away, sin(el - t); a plane of slope s under exaggeration e is
// tilted by atan(e s). And the preview's texture boost: feed marks of 0.4 um beside
// scallops of 94 um show in preview.png, and an envelope surface gets no boost. And the
// preview's colour range: the scallops', not the partly cut strip's at the map's edge
// nor the uncut cells', which are grey.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tests/support/sampled_field.h"
#include "tools/render/height_colours.h"
#include "tools/render/hillshade_png.h"
#include "tools/render/preview_png.h"
#include "tools/render/relief_shading.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = kRadPerDeg;

// nx x ny cells of side `spacing` from the origin with z = f(cell centre x, y).
ZMap mapOf(int64_t nx, int64_t ny, double spacing, const std::function<double(double, double)>& f) {
  return sampledField(0, 0, nx, ny, spacing, f);
}

// The plane through the origin that falls by tan(tilt) per mm towards the azimuth
// `downhillDeg` (clockwise from north): its normal leans by `tilt` that way.
ZMap tiltedPlane(double tiltDeg, double downhillDeg, int64_t n = 40, double spacing = 0.01) {
  const double s = std::tan(tiltDeg * kDeg), az = downhillDeg * kDeg;
  return mapOf(n, n, spacing,
               [&](double x, double y) { return -s * (x * std::sin(az) + y * std::cos(az)); });
}

std::vector<double> lambertOf(const ZMap& map, double exaggeration, const Light& light) {
  return lambert(slopes(reduceMap(map, 1600)), exaggeration, light);
}

TEST(ReliefShading, FlatFloorIsSinOfTheElevationEverywhere) {
  const ZMap flat = mapOf(30, 20, 0.002, [](double, double) { return -0.25; });
  for (double el : {10.0, 45.0, 90.0})
    for (double az : {0.0, 137.0, 315.0}) {
      for (double v : lambertOf(flat, 50, {az, el}))
        ASSERT_NEAR(v, std::sin(el * kDeg), 1e-15) << "az " << az << " el " << el;
    }
}

TEST(ReliefShading, FacetsTowardsAndAwayFromTheLight) {
  const Light light;  // from 315 degrees (north-west), 45 up
  for (double t : {5.0, 20.0, 40.0}) {
    // Falling towards the north-west: the normal leans towards the light.
    for (double v : lambertOf(tiltedPlane(t, 315), 1, light))
      ASSERT_NEAR(v, std::sin((45 + t) * kDeg), 1e-12) << t;
    // Falling towards the south-east: away from it.
    for (double v : lambertOf(tiltedPlane(t, 135), 1, light))
      ASSERT_NEAR(v, std::sin((45 - t) * kDeg), 1e-12) << t;
    // Falling towards the north-east, across the light: n . l = cos(t) sin(el).
    for (double v : lambertOf(tiltedPlane(t, 45), 1, light))
      ASSERT_NEAR(v, std::cos(t * kDeg) * std::sin(45 * kDeg), 1e-12) << t;
  }
  // Turned away by more than the elevation: in its own shadow, 0.
  for (double v : lambertOf(tiltedPlane(60, 135), 1, light)) ASSERT_EQ(v, 0.0);
}

TEST(ReliefShading, ExaggerationTiltsBySlopeTimesFactor) {
  // Slope 0.004 (a 2 um scallop flank over 0.5 mm), exaggerated 100 times: tilt
  // atan(0.4) towards the light from 200 degrees, 30 up.
  const double s = 0.004, e = 100, tilt = std::atan(e * s) / kDeg;
  const Light light{200, 30};
  for (double v : lambertOf(tiltedPlane(std::atan(s) / kDeg, 200), e, light))
    ASSERT_NEAR(v, std::sin((30 + tilt) * kDeg), 1e-12);
  // Exaggeration e of slope s shades as slope e s unexaggerated.
  const std::vector<double> a = lambertOf(tiltedPlane(std::atan(s) / kDeg, 77), e, light);
  const std::vector<double> b = lambertOf(tiltedPlane(std::atan(e * s) / kDeg, 77), 1, light);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], 1e-12);
}

TEST(ReliefShading, AutomaticExaggerationShowsATypicalSlopeAt35Degrees) {
  // A roof of slope 0.01 both sides (the ridge row's central difference is 0): the
  // typical slope is 0.01, tan(35 deg) / 0.01 = 70.02, two digits: 70.
  const ZMap roof =
      mapOf(40, 41, 0.01, [](double, double y) { return -0.01 * std::abs(y - 0.205); });
  EXPECT_DOUBLE_EQ(automaticExaggeration(slopes(reduceMap(roof, 1600))), 70);
  const ZMap flat = mapOf(10, 10, 0.01, [](double, double) { return 0.0; });
  EXPECT_EQ(automaticExaggeration(slopes(reduceMap(flat, 1600))), 1);
  EXPECT_EQ(reliefLegend(70, Light()).front(),
            "relief shading: heights \u00d7 70, light from 315\u00b0 at 45\u00b0");
  const std::vector<std::string> boosted = reliefLegend(4, Light{90, 30}, 5, 0.125);
  ASSERT_EQ(boosted.size(), 2u);
  EXPECT_EQ(boosted[0], "relief shading: heights \u00d7 4, light from 90\u00b0 at 30\u00b0");
  EXPECT_EQ(boosted[1], "texture finer than 125 \u00b5m: heights \u00d7 20");
}

// The 8-bit RGB pixels of a PNG.
struct Picture {
  int w = 0, h = 0;
  std::vector<uint8_t> rgb;
  const uint8_t* at(int x, int y) const { return &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]; }
};

Picture readPng(const std::string& path) {
  Picture p;
  auto in = OIIO::ImageInput::open(path);
  if (!in) return p;
  EXPECT_EQ(in->spec().nchannels, 3);
  p.w = in->spec().width;
  p.h = in->spec().height;
  p.rgb.resize(size_t(p.w) * size_t(p.h) * 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, p.rgb.data()));
  return p;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class HillshadePicture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("scallop-hillshade-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// The map's top left pixel: both pictures leave a 16 px margin, and without a title
// the map starts there.
constexpr int kMargin = 16;

TEST_F(HillshadePicture, GreyIsRound255TimesLambert) {
  // 40 x 40 cells are enlarged 10 times to reach the 400 px minimum.
  const double t = 20, e = 3;
  HillshadeOptions o;
  o.exaggeration = e;
  o.light = {250, 35};
  const double returned = writeHillshadePng(tiltedPlane(t, 250), file("p.png"), o);
  EXPECT_EQ(returned, e);
  const Picture p = readPng(file("p.png"));
  ASSERT_GT(p.w, kMargin + 400);
  const double tilt = std::atan(e * std::tan(t * kDeg)) / kDeg;
  const int expected = int(std::lround(255 * std::sin((35 + tilt) * kDeg)));
  for (int y = kMargin; y < kMargin + 400; y += 7)
    for (int x = kMargin; x < kMargin + 400; x += 7)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(int(p.at(x, y)[c]), expected) << x << " " << y;
  // The flat floor under the default light: round(255 sin 45) = 180.
  writeHillshadePng(mapOf(40, 40, 0.01, [](double, double) { return 0.0; }), file("f.png"));
  EXPECT_EQ(int(readPng(file("f.png")).at(kMargin + 200, kMargin + 200)[0]), 180);
}

TEST_F(HillshadePicture, SameMapSameBytes) {
  const ZMap m = mapOf(300, 200, 0.002, [](double x, double y) {
    return 1e-3 * std::sin(40 * x) * std::cos(25 * y) + 2e-4 * std::cos(300 * x);
  });
  for (bool colour : {false, true}) {
    HillshadeOptions o;
    o.colour = colour;
    o.title = "determinism";
    writeHillshadePng(m, file("a.png"), o);
    writeHillshadePng(m, file("b.png"), o);
    const std::string a = slurp(file("a.png"));
    EXPECT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == slurp(file("b.png"))) << "colour " << colour;
  }
}

TEST_F(HillshadePicture, BadLightOrExaggerationNamesTheFieldAndWritesNothing) {
  const ZMap m = tiltedPlane(10, 0);
  struct Row {
    Light light;
    double exaggeration;
    const char* field;
  };
  for (const Row& r :
       {Row{{NAN, 45}, NAN, "--azimuth"}, Row{{INFINITY, 45}, NAN, "--azimuth"},
        Row{{315, 0}, NAN, "--elevation"}, Row{{315, 90.5}, NAN, "--elevation"},
        Row{{315, NAN}, NAN, "--elevation"}, Row{{315, 45}, 0, "--exaggeration"},
        Row{{315, 45}, -2, "--exaggeration"}, Row{{315, 45}, INFINITY, "--exaggeration"},
        Row{{315, 45}, 2e6, "--exaggeration"}}) {
    HillshadeOptions o;
    o.light = r.light;
    o.exaggeration = r.exaggeration;
    try {
      writeHillshadePng(m, file("bad.png"), o, "--");
      ADD_FAILURE() << "no error for " << r.field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), r.field);
    }
    EXPECT_TRUE(fs::is_empty(dir_)) << r.field;
  }
}

// The scallops of a ball R = 3 mm raster with step-over 1.5 mm (94 um), and along x
// the feed marks of fz = 0.1 mm, both circles of radius R (docs/teeth.md): what the
// teeth model leaves along a pass.
double arcs(double u, double period, double radius) {
  const double d = u - period * std::round(u / period);
  return radius - std::sqrt(radius * radius - d * d);
}
ZMap scallops(bool marks) {
  return mapOf(600, 600, 0.005, [marks](double x, double y) {
    return arcs(y, 1.5, 3) + (marks ? arcs(x, 0.1, 3) : 0.0) - 0.1;
  });
}

// Grey levels of the preview along the picture row through y (mm), over x in [0, 0.5] mm.
std::vector<int> previewRow(const Picture& p, double yMm) {
  const int row = kMargin + int((3.0 - yMm) / 0.005);  // 600 cells, 1 px each, north up
  std::vector<int> out;
  for (int a = 0; a < 100; ++a) {
    const uint8_t* c = p.at(kMargin + a, row);
    out.push_back(int(c[0]) + int(c[1]) + int(c[2]));
  }
  return out;
}

TEST_F(HillshadePicture, PreviewShowsFeedMarksBesideScallops) {
  const double exaggeration = writePreviewPng(scallops(false), file("envelope.png"));
  writePreviewPng(scallops(true), file("teeth.png"));
  PreviewOptions plain;
  plain.textureBoost = 1;
  writePreviewPng(scallops(true), file("plain.png"), plain);
  const Picture envelope = readPng(file("envelope.png")), teeth = readPng(file("teeth.png"));
  const Picture unboosted = readPng(file("plain.png"));
  ASSERT_GT(teeth.w, 600);
  auto swing = [](const std::vector<int>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  // Rows near a pass centre (valley) and up a flank: the envelope's row is one colour;
  // the teeth's swings with the marks (0.4 um of 94 um: colour alone moves < 1 level),
  // by about a fifth of its brightness (r + g + b ~ 170 on the dark end of viridis),
  // twice as much or more as without the texture boost.
  for (double y : {1.52, 1.9}) {
    EXPECT_EQ(swing(previewRow(envelope, y)), 0) << y;
    const int boosted = swing(previewRow(teeth, y)), once = swing(previewRow(unboosted, y));
    EXPECT_GE(boosted, 30) << y;
    EXPECT_GE(boosted, 2 * once) << y;
  }
  // The scallops' slope |d| / sqrt(R^2 - d^2) grows with the distance d from the pass
  // centre, uniform in [0, 0.75] mm: the 75th percentile is at d = 0.5625 mm, slope
  // 0.19089, and tan(35 deg) / 0.19089 = 3.668, two digits 3.7.
  EXPECT_DOUBLE_EQ(exaggeration, 3.7);
  const HeightRaster r = reduceMap(scallops(false), 1600);
  EXPECT_EQ(automaticTextureBoost(slopes(r), textureSlopes(r, 12), exaggeration), 1)
      << "an envelope surface's smooth curvature is not texture";
  const HeightRaster m = reduceMap(scallops(true), 1600);
  EXPECT_GT(automaticTextureBoost(slopes(m), textureSlopes(m, 12), exaggeration), 2);
}

// A ball R = 3 mm raster along x with step-over 0.5 mm (cusps 10.44 um high) over
// 4 x 3 mm, floor at -0.5 mm; beyond its last pass (y = 2.5 mm) only the side of a
// smaller ball (R = 0.6 mm) reached the stock, rising 268 um to the north edge, as the
// bull's corner does in the default job. That strip is 17% of the map and rises to
// 26 times the cusps' height.
double scallopsWithEdgeStrip(double y) {
  return -0.5 + (y > 2.5 ? arcs(y - 2.5, 10, 0.6) : arcs(y, 0.5, 3));
}
const double kCuspMm = -0.5 + 3 - std::sqrt(9 - 0.25 * 0.25);

TEST_F(HillshadePicture, ColourRangeIgnoresThePartlyCutEdge) {
  const ZMap map = mapOf(400, 300, 0.01, [](double, double y) { return scallopsWithEdgeStrip(y); });
  const auto [low, high] = robustRange(reduceMap(map, 1600));
  // The scallops take the whole colour bar: floor to cusps (cell centres miss the
  // exact cusp by at most half a cell: 0.4 um). Percentiles alone (the range before
  // the edge flanks were left out) put the top 28 um above the floor, the cusps at a
  // third of the bar.
  EXPECT_NEAR(low, -0.5, 5e-6);  // valley cells lie 0.005 mm off the pass: 4.2 nm up
  EXPECT_LE(high, kCuspMm + 1e-9);
  EXPECT_GE(high, kCuspMm - 0.5e-3);
}

TEST_F(HillshadePicture, UncutCellsAreGreyAndOutsideTheRange) {
  // East of x = 3.5 mm no move reached the stock (top 0); between 3 and 3.5 mm a flank
  // falls from it to the scallops.
  auto z = [](double x, double y) {
    const double cut = scallopsWithEdgeStrip(y);
    return x > 3.5 ? 0.0 : x > 3 ? cut * (3.5 - x) / 0.5 : cut;
  };
  const ZMap map = mapOf(400, 300, 0.01, z);
  const auto [low, high] = robustRange(reduceMap(map, 1600), 0.0);
  EXPECT_NEAR(low, -0.5, 5e-6);  // valley cells lie 0.005 mm off the pass: 4.2 nm up
  EXPECT_LE(high, kCuspMm + 1e-9);
  EXPECT_GE(high, kCuspMm - 0.5e-3);

  PreviewOptions o;
  o.uncutHeight = 0;
  writePreviewPng(map, file("uncut.png"), o);
  writePreviewPng(map, file("untold.png"));
  const Picture told = readPng(file("uncut.png")), untold = readPng(file("untold.png"));
  ASSERT_GT(told.w, kMargin + 400);
  // 400 x 300 cells, 1 px each, north up: column 380 is uncut, column 100 cut.
  auto grey = [](const uint8_t* c) { return c[0] == 185 && c[1] == 185 && c[2] == 185; };
  for (int row = kMargin; row < kMargin + 300; row += 10) {
    EXPECT_TRUE(grey(told.at(kMargin + 380, row))) << row;
    EXPECT_FALSE(grey(told.at(kMargin + 100, row))) << row;
    EXPECT_FALSE(grey(untold.at(kMargin + 380, row))) << row;
  }
  // The legend names the grey: the picture with uncut cells is one line taller.
  EXPECT_GT(told.h, untold.h);
}

}  // namespace
}  // namespace scallop
