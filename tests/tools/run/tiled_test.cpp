// Maps computed in bands (tools/run/tiled_simulation.h): the same heights, bit for bit, as
// the in-memory path, written as tiled OpenEXR and streamed GSF, and band ranges run
// by separate processes that `scallop merge` assembles into the same files.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_harness.h"
#include "tools/io/height_images.h"
#include "tools/run/tiled_simulation.h"

namespace fs = std::filesystem;

namespace {

using scallop::test::CliRun;
using scallop::test::slurp;

class Tiled : public scallop::test::CliFixture {
 protected:
  // 200 x 300 cells: 32-row bands give 10 bands, the last one partial (12 rows).
  std::string job() {
    return write("job.json", R"({
      "tool":  {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
      "stock": {"min": [0.1, -0.3, -2], "max": [2.1, 2.7, 0]},
      "grid":  {"spacing": 0.01},
      "path":  {"raster": {"direction": "x", "step_over": 1.1, "depth": 0.3, "lead_deg": 5}}
    })")
        .string();
  }
  void simulate(const std::string& out, const std::string& extra) {
    const CliRun r = run("simulate " + job() + " -o " + path(out) + " " + extra);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  nlohmann::json report(const std::string& out) {
    return nlohmann::json::parse(slurp(path(out) + "/report.json"));
  }
  void expectSameHeights(const std::string& a, const std::string& b) {
    const scallop::ZMap ea = scallop::readHeightsExr(path(a) + "/heights.exr");
    const scallop::ZMap eb = scallop::readHeightsExr(path(b) + "/heights.exr");
    EXPECT_EQ(ea.nx(), eb.nx());
    EXPECT_EQ(ea.ny(), eb.ny());
    EXPECT_TRUE(ea.heights() == eb.heights()) << a << " vs " << b;
    EXPECT_EQ(slurp(path(a) + "/heights.gsf"), slurp(path(b) + "/heights.gsf"));
    EXPECT_EQ(slurp(path(a) + "/preview.png"), slurp(path(b) + "/preview.png"));
    const nlohmann::json ra = report(a), rb = report(b);
    for (const char* key : {"min_height", "max_height", "max_scallop_height", "floor_z"})
      EXPECT_EQ(ra["measurements"][key], rb["measurements"][key]) << key;
    EXPECT_EQ(ra["grid"], rb["grid"]);
    EXPECT_EQ(ra["inputs"], rb["inputs"]);
  }
};

TEST_F(Tiled, BandsGiveTheInMemoryMapBitForBit) {
  simulate("mem", "");
  simulate("tiled", "--tile-rows 32 --threads 2");
  expectSameHeights("mem", "tiled");
  const nlohmann::json r = report("tiled");
  EXPECT_EQ(r["tiled"]["bands"], 10);
  EXPECT_EQ(r["tiled"]["band_rows"], 32);
  EXPECT_FALSE(report("mem").contains("tiled"));
  // The float32 files hold what the doubles round to.
  const scallop::ZMap gsf = scallop::readHeightsGsf(path("tiled") + "/heights.gsf");
  EXPECT_EQ(gsf.nx(), 200);
  EXPECT_EQ(gsf.ny(), 300);
}

TEST_F(Tiled, ExrIsTiledInBandRows) {
  simulate("tiled", "--tiled --tile-rows 32");
  auto in = OIIO::ImageInput::open(path("tiled") + "/heights.exr");
  ASSERT_TRUE(in);
  EXPECT_GT(in->spec().tile_width, 0);
  EXPECT_EQ(in->spec().tile_height, 32);
  in->close();
  simulate("mem", "");
  auto plain = OIIO::ImageInput::open(path("mem") + "/heights.exr");
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->spec().tile_width, 0);  // the in-memory path is unchanged
}

TEST_F(Tiled, BandRangesInTwoProcessesMergeToTheSingleRun) {
  simulate("one", "--tile-rows 32");
  simulate("split", "--tile-rows 32 --bands 4:10");
  simulate("split", "--tile-rows 32 --bands 0:4 --threads 1");
  EXPECT_FALSE(fs::exists(path("split") + "/heights.exr"));  // nothing until merged
  const CliRun m = run("merge " + path("split") + " --json");
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(nlohmann::json::parse(m.out)["tiled"]["bands"], 10);
  expectSameHeights("one", "split");
}

TEST_F(Tiled, MergeNamesAMissingBandAndWritesNothing) {
  simulate("split", "--tile-rows 32 --bands 0:4");
  simulate("split", "--tile-rows 32 --bands 5:10");
  const CliRun m = run("merge " + path("split"));
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("band-4.json"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("--bands 4:5"), std::string::npos) << m.err;
  for (const char* f : {"heights.exr", "heights.gsf", "preview.png", "report.json"})
    EXPECT_FALSE(fs::exists(path("split") + "/" + f)) << f;
}

TEST_F(Tiled, MergeRefusesBandsOfAnotherRun) {
  simulate("split", "--tile-rows 32 --bands 0:5");
  simulate("other", "--tile-rows 64 --bands 0:5");
  // band-5.json of a 64-row layout (bands 0..4 there) cannot exist; use a foreign band 3.
  fs::copy_file(path("other") + "/band-3.json", path("split") + "/band-3.json",
                fs::copy_options::overwrite_existing);
  simulate("split", "--tile-rows 32 --bands 5:10");
  const CliRun m = run("merge " + path("split"));
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("band-3.json"), std::string::npos) << m.err;
  EXPECT_FALSE(fs::exists(path("split") + "/heights.exr"));
}

TEST_F(Tiled, BadBandRangesAndEmptyFoldersAreBadInput) {
  for (const char* range : {"3:2", "0:11", "x", "2"}) {
    const CliRun r =
        run("simulate " + job() + " -o " + path("o") + " --tile-rows 32 --bands " + range);
    EXPECT_EQ(r.status, 1) << range;
    EXPECT_NE(r.err.find("--bands"), std::string::npos) << r.err;
  }
  fs::create_directories(path("empty"));
  const CliRun m = run("merge " + path("empty"));
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("no band files"), std::string::npos) << m.err;
  EXPECT_EQ(run("merge").status, 2);
}

TEST(BandLayout, BandsAreBoundedAndWholeTiles) {
  scallop::GridSpec g;
  g.nx = g.ny = 20000;  // 20 x 20 mm at 1 um
  g.spacing = 0.001;
  const scallop::BandLayout l = scallop::bandLayout(g, 0);
  EXPECT_LE(double(l.bandRows) * double(g.nx) * sizeof(double), 256.0 * (1 << 20));
  EXPECT_EQ(l.bandRows % l.tileHeight, 0);
  EXPECT_LE(l.tileHeight, 256);
  EXPECT_EQ(l.bands, (g.ny + l.bandRows - 1) / l.bandRows);
  EXPECT_EQ(scallop::bandLayout(g, 1000).bandRows, 768);  // whole 256-row tiles
  EXPECT_EQ(scallop::bandLayout(g, 7).tileHeight, 7);
}

TEST(BandLayout, BandCellCentresAreTheFullGridsToTheBit) {
  scallop::GridSpec g;
  g.originX = 0.1;
  g.originY = -0.3;
  g.spacing = 0.003;
  g.nx = 7;
  g.ny = 1000;
  const scallop::BandLayout l = scallop::bandLayout(g, 96);
  int64_t rows = 0;
  for (int64_t b = 0; b < l.bands; ++b) {
    const scallop::GridSpec band = l.bandGrid(b, g);
    rows += band.ny;
    for (int64_t j = 0; j < band.ny; ++j)
      ASSERT_EQ(band.cellCentreY(j), g.cellCentreY(band.offsetJ + j));
    EXPECT_EQ(band.cellCentreX(3), g.cellCentreX(3));
  }
  EXPECT_EQ(rows, g.ny);
  EXPECT_EQ(l.bandGrid(0, g).offsetJ + l.bandGrid(0, g).ny, g.ny);  // band 0 is the top
}

}  // namespace
