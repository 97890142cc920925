// A solid stock's preview.png and `export --hillshade --colour` of the same heights are
// one picture (tools/render/preview_png.h): a faceted frustum blank machined all over,
// its map area compared pixel by pixel (mean luminance and colour within 2 %, and
// nearly every pixel alike), cells off the blank white in both ("no material" in the
// legend). The preview once lit every cell by the ambient term alone when a cell held
// no material (the texture's box mean took the NaN).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/vec3.h"
#include "tests/support/cli_harness.h"
#include "tools/io/height_export.h"
#include "tools/render/png_canvas.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

// The frustum: radius 8 at z = -4 to radius 3 at z = 0 about (10, 10), kSides facets
// around, closed by fans; outward, counter-clockwise facets.
constexpr int kSides = 32;
constexpr double kCx = 10, kCy = 10, kR0 = 8, kZ0 = -4, kR1 = 3, kZ1 = 0;

std::string frustumStl() {
  auto at = [](double r, int k, double z) {
    const double a = 2 * kPi * (k % kSides) / kSides;
    return Vec3{kCx + r * std::cos(a), kCy + r * std::sin(a), z};
  };
  const Vec3 bottom{kCx, kCy, kZ0}, top{kCx, kCy, kZ1};
  std::ostringstream out;
  out.precision(17);
  out << "solid frustum\n";
  auto facet = [&](Vec3 a, Vec3 b, Vec3 c) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (const Vec3& p : {a, b, c}) out << "vertex " << p.x << " " << p.y << " " << p.z << "\n";
    out << "endloop\nendfacet\n";
  };
  for (int k = 0; k < kSides; ++k) {
    const Vec3 b0 = at(kR0, k, kZ0), b1 = at(kR0, k + 1, kZ0);
    const Vec3 t0 = at(kR1, k, kZ1), t1 = at(kR1, k + 1, kZ1);
    facet(b0, b1, t1);
    facet(b0, t1, t0);
    facet(bottom, b1, b0);
    facet(top, t0, t1);
  }
  out << "endsolid frustum\n";
  return out.str();
}

// Passes along x, 0.5 mm apart, 0.3 mm under the (round) frustum, rapids above it.
std::string finishingPath() {
  std::ostringstream out;
  for (double y = 2.25; y < 18; y += 0.5) {
    out << "\n1 " << y << " 2\n";
    for (double x = 1; x <= 19; x += 0.25) {
      const double r = std::hypot(x - kCx, y - kCy);
      const double top = r <= kR1 ? kZ1 : kZ1 - (r - kR1) * (kZ1 - kZ0) / (kR0 - kR1);
      out << x << " " << y << " " << std::max(top, kZ0) - 0.3 << "\n";
    }
    out << "19 " << y << " 2\n";
  }
  return out.str();
}

struct Picture {
  int w = 0, h = 0;
  std::vector<uint8_t> rgb;
  const uint8_t* at(int x, int y) const { return &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]; }
};

Picture readPng(const std::string& path) {
  Picture p;
  auto in = OIIO::ImageInput::open(path);
  if (!in) return p;
  p.w = in->spec().width;
  p.h = in->spec().height;
  p.rgb.resize(size_t(p.w) * size_t(p.h) * 3);
  EXPECT_EQ(in->spec().nchannels, 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, p.rgb.data()));
  return p;
}

double luminance(const uint8_t* c) {
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

class SolidStockPreview : public test::CliFixture {};

TEST_F(SolidStockPreview, EqualsTheExportPictureOfItsHeights) {
  write("blank.stl", frustumStl());
  write("p.txt", finishingPath());
  write("job.json", R"({"tool": {"type": "ball", "radius": 0.5}, "stock": {"stl": "blank.stl"},
    "grid": {"spacing": 0.2}, "path": {"file": "p.txt"}})");
  const test::CliRun sim = run("simulate " + path("job.json") + " -o " + path("out"));
  ASSERT_EQ(sim.status, 0) << sim.err;
  const test::CliRun exp = run("export " + path("out/heights.gsf") + " --to " + path("x.png") +
                               " --hillshade --colour");
  ASSERT_EQ(exp.status, 0) << exp.err;
  const Picture preview = readPng(path("out/preview.png")), shown = readPng(path("x.png"));

  // The map's place in both: below the title, enlarged to at least 400 px (PreviewOptions).
  const ZMap heights = readHeightFile(path("out/heights.gsf"));
  const int nx = int(heights.nx()), ny = int(heights.ny());
  const int up = std::max(1, std::min((400 + std::max(nx, ny) - 1) / std::max(nx, ny),
                                      1600 / std::max(nx, ny)));
  const int mapX = 16, mapY = 16 + 2 * png::kCapHeightPx + 12;
  ASSERT_GE(preview.w, mapX + nx * up);
  ASSERT_GE(shown.w, mapX + nx * up);
  ASSERT_GE(std::min(preview.h, shown.h), mapY + ny * up);

  double lumP = 0, lumX = 0, meanP[3] = {0, 0, 0}, meanX[3] = {0, 0, 0};
  int64_t pixels = 0, unlike = 0, material = 0;
  const double lit = 0.3 * 255;  // the ambient term alone: an unlit picture's brightest
  int64_t aboveAmbient = 0;
  // One pixel inside each cell (the frame is drawn over the outermost ones).
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int x = mapX + i * up + up / 2, y = mapY + j * up + up / 2;
      const uint8_t *p = preview.at(x, y), *q = shown.at(x, y);
      lumP += luminance(p);
      lumX += luminance(q);
      for (int c = 0; c < 3; ++c) meanP[c] += p[c], meanX[c] += q[c];
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(p[c]) - int(q[c])));
      unlike += worst > 8;
      ++pixels;
      // Cells off the blank hold no material: white in both.
      const double h = heights.at(i, ny - 1 - j);
      if (std::isnan(h)) {
        EXPECT_EQ(int(p[0]) + p[1] + p[2], 3 * 255) << i << " " << j;
        EXPECT_EQ(int(q[0]) + q[1] + q[2], 3 * 255) << i << " " << j;
      } else {
        ++material;
        aboveAmbient += std::max({p[0], p[1], p[2]}) > lit;
      }
    }
  ASSERT_GT(material, pixels / 3);
  ASSERT_LT(material, pixels);  // the square's corners are off the blank
  EXPECT_NEAR(lumP / double(pixels), lumX / double(pixels), 0.02 * lumX / double(pixels));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(meanP[c] / double(pixels), meanX[c] / double(pixels), 0.02 * 255) << c;
  EXPECT_LT(unlike, pixels / 50) << "pixels that differ by more than 8 levels";
  // Lit by the relief, not by the ambient term alone (which keeps every channel at
  // most 0.3 of 255).
  EXPECT_GT(aboveAmbient, material / 2);
}

}  // namespace
}  // namespace scallop
