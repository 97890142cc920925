// `scallop render` as a user runs it: every kind of height file scallop reads (GSF, EXR,
// X3P, 16-bit TIFF and PNG, a folder of unmerged bands) gives a picture of --size; the
// same bytes on 1 and 2 threads; and bad input (an unreadable file, a size of 0 or above
// 16384, an elevation outside (0, 90], a region outside the map) is an input error
// naming the option, with no PNG left behind. `simulate --view` writes DIR/view.png.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/support/cli_harness.h"
#include "tests/tools/cli/bad_input_matrix.h"
#include "tools/io/height_images.h"

namespace scallop::test {
namespace {

class RenderCli : public CliFixture {
 protected:
  // 120 x 80 cells of 0.01 mm: ripples and a block.
  std::string writeMap(const std::string& name = "h.gsf") {
    GridSpec g;
    g.spacing = 0.01, g.nx = 120, g.ny = 80;
    ZMap m(g, 0.0);
    for (int64_t j = 0; j < g.ny; ++j)
      for (int64_t i = 0; i < g.nx; ++i) {
        const double x = g.cellCentreX(i), y = g.cellCentreY(j);
        m.at(i, j) = 0.005 * std::sin(20 * x) + (x > 0.5 && x < 0.7 && y > 0.3 ? 0.02 : 0.0);
      }
    const std::string file = path(name);
    writeHeightsGsf(m, file, "test map");
    return file;
  }
  static std::vector<uint8_t> pixels(const std::string& file) {
    auto in = OIIO::ImageInput::open(file);
    if (!in) return {};
    std::vector<uint8_t> rgb(size_t(in->spec().width) * size_t(in->spec().height) * 3);
    if (in->spec().nchannels != 3 || !in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb.data()))
      return {};
    return rgb;
  }
  static std::pair<int, int> pngSize(const std::string& file) {
    auto in = OIIO::ImageInput::open(file);
    if (!in) return {0, 0};
    return {in->spec().width, in->spec().height};
  }
};

TEST_F(RenderCli, EveryHeightFileKindGivesAPictureOfTheSize) {
  const std::string gsf = writeMap();
  for (const std::string ext : {".exr", ".x3p", ".tif", ".png"}) {
    const CliRun e = run("export " + gsf + " --to " + path("h" + ext));
    ASSERT_EQ(e.status, 0) << e.err;
  }
  for (const std::string ext : {".gsf", ".exr", ".x3p", ".tif", ".png"}) {
    const std::string out = path("r" + std::string(ext.begin() + 1, ext.end()) + ".png");
    const CliRun r = run("render " + path("h" + ext) + " -o " + out + " --size 300 200");
    EXPECT_EQ(r.status, 0) << ext << "\n" << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(pngSize(out), std::make_pair(300, 200)) << ext;
  }
}

TEST_F(RenderCli, BandsUnmergedRenderLikeTheMergedMap) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -1], "max": [3, 2, 0]}, "grid": {"spacing": 0.02},
    "path": {"raster": {"direction": "x", "step_over": 0.5, "depth": 0.1}}})";
  write("job.json", job);
  const std::string dir = path("bands");
  ASSERT_EQ(
      run("simulate " + path("job.json") + " -o " + dir + " --tile-rows 32 --bands 0:4").status, 0);
  const CliRun r = run("render " + dir + " -o " + path("bands.png") + " --size 300 200");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(run("merge " + dir).status, 0);
  ASSERT_EQ(run("render " + dir + "/heights.gsf -o " + path("merged.png") +
                " --size 300 200 --title " + dir)
                .status,
            0);
  // The merged GSF holds float32 heights, the bands float64: the same picture but for
  // a few pixels where a rounded height tips a colour or a shadow's edge.
  const std::vector<uint8_t> a = pixels(path("bands.png")), b = pixels(path("merged.png"));
  ASSERT_EQ(a.size(), size_t(300 * 200 * 3));
  ASSERT_EQ(a.size(), b.size());
  size_t differ = 0;
  for (size_t k = 0; k < a.size(); ++k) differ += std::abs(int(a[k]) - int(b[k])) > 2;
  EXPECT_LT(differ, a.size() / 200);
}

TEST_F(RenderCli, SimulateViewWritesTheSamePicture) {
  write("job.json", R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -1], "max": [3, 2, 0]}, "grid": {"spacing": 0.02},
    "path": {"raster": {"direction": "x", "step_over": 0.5, "depth": 0.1}}})");
  const CliRun r = run("simulate " + path("job.json") + " -o " + path("out") + " --view");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(pngSize(path("out/view.png")), std::make_pair(1600, 1000));
  EXPECT_NE(slurp(path("out/report.json")).find("\"view.png\""), std::string::npos);
  // In bands the map is never whole: refused before computing, naming the option.
  const CliRun tiled =
      run("simulate " + path("job.json") + " -o " + path("tiled") + " --view --tiled");
  EXPECT_EQ(tiled.status, 1);
  EXPECT_NE(tiled.err.find("--view"), std::string::npos) << tiled.err;
  EXPECT_FALSE(fs::exists(path("tiled/view.png")));
}

TEST_F(RenderCli, SameBytesOnOneAndTwoThreads) {
  const std::string gsf = writeMap();
  ASSERT_EQ(run("render " + gsf + " -o " + path("one.png") + " --threads 1 --size 400 300").status,
            0);
  ASSERT_EQ(run("render " + gsf + " -o " + path("two.png") + " --threads 2 --size 400 300").status,
            0);
  const std::string one = slurp(path("one.png")), two = slurp(path("two.png"));
  EXPECT_FALSE(one.empty());
  EXPECT_TRUE(one == two);
}

TEST_F(BadInputMatrix, Render) {
  GridSpec g;
  g.spacing = 0.01, g.nx = 30, g.ny = 20;
  ZMap m(g, 0.0);
  writeHeightsGsf(m, (dir_ / "h.gsf").string(), "flat");
  const std::string map = slurp(dir_ / "h.gsf");
  fs::remove(dir_ / "h.gsf");
  const std::string ok = "render @/h.gsf -o @/out.png";
  std::vector<BadInputRow> rows = {
      {"unreadable file",
       {{"bad.gsf", "not a GSF"}},
       "render @/bad.gsf -o @/out.png",
       1,
       {"@/bad.gsf"}},
      {"missing file", {}, "render @/none.gsf -o @/out.png", 1, {"@/none.gsf"}},
      {"size 0", {}, ok + " --size 0 100", 1, {"--size"}},
      {"size above 16384", {}, ok + " --size 16385 100", 1, {"--size", "16384"}},
      {"view elevation 0", {}, ok + " --view 30 0", 1, {"--view", "(0, 90]"}},
      {"view elevation above 90", {}, ok + " --view 30 91", 1, {"--view", "(0, 90]"}},
      {"light elevation negative", {}, ok + " --light 315 -5", 1, {"--light", "(0, 90]"}},
      {"exaggeration 0", {}, ok + " --exaggeration 0", 1, {"--exaggeration"}},
      {"region outside the map", {}, ok + " --region 5 5 6 6", 1, {"--region"}},
      {"region of one cell", {}, ok + " --region 0 0 0.01 0.01", 1, {"--region"}},
      {"not a png", {}, "render @/h.gsf -o @/out.jpg", 1, {"-o"}},
      {"unknown projection", {}, ok + " --projection fisheye", 2, {}},
  };
  for (BadInputRow& row : rows) {
    row.files.push_back({"h.gsf", map});
    check(row);
  }
}

}  // namespace
}  // namespace scallop::test
