// `scallop export --hillshade` as a user runs it: a tilted plane read from a GSF file
// comes out as the grey level round(255 sin(el + tilt)) (tests/tools/render/hillshade_test.cpp
// derives it); --region crops; usage errors exit 2 and bad values exit 1, naming the
// option, with nothing on stdout and no output file.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/constants.h"
#include "tests/support/cli_harness.h"
#include "tools/io/height_images.h"

namespace scallop::test {
namespace {

constexpr double kDeg = kRadPerDeg;

class HillshadeCli : public CliFixture {
 protected:
  // 50 x 40 cells of 0.01 mm falling by `slope` per mm towards the west (-x).
  std::string writePlane(double slope) {
    GridSpec g;
    g.spacing = 0.01;
    g.nx = 50;
    g.ny = 40;
    ZMap m(g, 0.0);
    for (int64_t j = 0; j < g.ny; ++j)
      for (int64_t i = 0; i < g.nx; ++i) m.at(i, j) = slope * g.cellCentreX(i) - 0.1;
    const std::string file = path("plane.gsf");
    writeHeightsGsf(m, file, "plane");
    return file;
  }
  void expectFailure(const std::string& args, int status, const std::string& needle) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, status) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(path("out.png"))) << args;
  }
};

struct Png {
  int w = 0, h = 0;
  std::vector<uint8_t> rgb;
};

Png readPng(const std::string& file) {
  Png p;
  auto in = OIIO::ImageInput::open(file);
  if (!in) return p;
  p.w = in->spec().width;
  p.h = in->spec().height;
  p.rgb.resize(size_t(p.w) * size_t(p.h) * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, p.rgb.data());
  return p;
}

TEST_F(HillshadeCli, TiltedPlaneGivesTheLambertGrey) {
  // Slope 0.002 exaggerated 200 times: tilt atan(0.4) towards the west; the light from
  // the west (270), 40 degrees up: grey round(255 sin(40 + 21.8 deg)) = 225.
  const std::string gsf = writePlane(0.002);
  const CliRun r = run("export " + gsf + " --to " + path("out.png") +
                       " --hillshade --azimuth 270 --elevation 40 --exaggeration 200 --title ''");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("heights x 200"), std::string::npos) << r.err;
  const Png p = readPng(path("out.png"));
  ASSERT_GT(p.w, 400);
  // GSF heights are float32 metres: the slope is 0.002 to ~1e-7, the grey unchanged.
  const int grey = int(std::lround(255 * std::sin((40 + std::atan(0.4) / kDeg) * kDeg)));
  ASSERT_EQ(grey, 225);
  // The map is enlarged 8 times (50 x 40 cells to 400 x 320 px) inside the 16 px
  // margin (no title), every pixel that grey.
  int matching = 0;
  for (int y = 16; y < 16 + 320; ++y)
    for (int x = 16; x < 16 + 400; ++x) {
      const uint8_t* c = &p.rgb[(size_t(y) * size_t(p.w) + size_t(x)) * 3];
      matching += c[0] == grey && c[1] == grey && c[2] == grey;
    }
  EXPECT_EQ(matching, 400 * 320);
}

TEST_F(HillshadeCli, RegionColourAndAutomaticExaggeration) {
  const std::string gsf = writePlane(0.01);
  ASSERT_EQ(run("export " + gsf + " --to " + path("whole.png") + " --hillshade").status, 0);
  // Cells whose centres lie in [0.1, 0.3] x [0.1, 0.2] mm: 20 x 10 of them.
  const CliRun r = run("export " + gsf + " --to " + path("part.png") +
                       " --hillshade --colour --region 0.1 0.1 0.3 0.2 --title part");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("20 x 10 cells"), std::string::npos) << r.err;
  // Automatic: tan(35 deg) / 0.01 = 70.02, to two digits.
  EXPECT_NE(r.err.find("heights x 70"), std::string::npos) << r.err;
  const Png whole = readPng(path("whole.png")), part = readPng(path("part.png"));
  ASSERT_GT(whole.w, 0);
  ASSERT_GT(part.w, 0);
  bool coloured = false;
  for (size_t k = 0; k < part.rgb.size(); k += 3)
    coloured = coloured || part.rgb[k] != part.rgb[k + 2];
  EXPECT_TRUE(coloured) << "--colour draws viridis";
}

// One case of each check (scallop starts in ~0.5 s, so the cases are few): the values
// each field takes are tested on writeHillshadePng itself (hillshade_test.cpp).
TEST_F(HillshadeCli, BadArgumentsExit1Or2AndWriteNothing) {
  const std::string gsf = writePlane(0.01);
  const std::string out = " --to " + path("out.png") + " --hillshade";
  expectFailure("export " + gsf + " --to " + path("out.tif") + " --hillshade", 2, "--hillshade");
  expectFailure("export " + gsf + " --to " + path("out.png") + " --azimuth 10", 2, "--azimuth");
  expectFailure("export " + gsf + out + " --elevation 95", 1, "--elevation");
  expectFailure("export " + gsf + out + " --exaggeration nan", 1, "--exaggeration");
  expectFailure("export " + gsf + out + " --region 0.3 0 0.1 0.2", 1, "--region");
  expectFailure("export " + path("missing.gsf") + out, 1, "missing.gsf");
  // Nothing but the input is left, not even a temporary file.
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir_)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"plane.gsf"});
}

TEST_F(HillshadeCli, HelpNamesTheOptions) {
  const CliRun r = run("export --help");
  ASSERT_EQ(r.status, 0);
  for (const char* o : {"--hillshade", "--azimuth", "--elevation", "--exaggeration", "--colour",
                        "--region", "--title"})
    EXPECT_NE(r.out.find(o), std::string::npos) << o;
}

}  // namespace
}  // namespace scallop::test
