// The height-format table (tools/io/height_formats.h): every entry with a reader reads
// back what its writer wrote (grid, heights to the file's precision, NaN cells, and the
// frame where the entry says it keeps one); the lookup ignores the extension's case;
// an unknown extension is refused naming the ones expected.
#include "tools/io/height_formats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tests/support/sampled_field.h"

namespace scallop::test {
namespace {

// Heights of a few mm with one cell without material (NaN).
ZMap sampleMap() {
  ZMap map = indexedField(-1.25, 3.5, 9, 6, 0.125, [](int64_t i, int64_t j) {
    return std::sin(0.7 * double(i)) - 0.3 * double(j);
  });
  map.at(4, 2) = NAN;
  return map;
}

std::string errorOf(const std::string& path, bool reading) {
  return inputErrorMessage([&] { heightFormatOf(path, reading); });
}

class HeightFormats : public CliFixture {};

TEST_F(HeightFormats, EveryReaderReadsBackItsWriter) {
  const ZMap map = sampleMap();
  const std::string frame = "origin (0, 0, 1) mm, u (1, 0, 0), normal (0, 0, 1)";
  int readers = 0;
  for (const HeightFormat& f : heightFormats()) {
    if (!f.read) continue;
    ++readers;
    const std::string file = path(std::string("h") + f.extension);
    f.write(map, file, "a title", frame);
    std::string back = "unset";
    const ZMap read = f.read(file, &back);
    EXPECT_EQ(back, f.keepsFrame ? frame : "") << f.extension;
    const GridSpec &g = map.grid(), &b = read.grid();
    ASSERT_EQ(b.nx, g.nx) << f.extension;
    ASSERT_EQ(b.ny, g.ny) << f.extension;
    EXPECT_NEAR(b.spacing, g.spacing, 1e-12) << f.extension;
    EXPECT_NEAR(b.originX, g.originX, 1e-9) << f.extension;
    EXPECT_NEAR(b.originY, g.originY, 1e-9) << f.extension;
    for (int64_t j = 0; j < g.ny; ++j)
      for (int64_t i = 0; i < g.nx; ++i) {
        const double z = map.at(i, j), r = read.at(i, j);
        if (std::isnan(z)) {
          EXPECT_EQ(std::isnan(r), f.keepsNoMaterial) << f.extension;
          continue;
        }
        // float32 files hold the height to 2^-24 of its size (and the m <-> mm factor).
        EXPECT_NEAR(r, z, 1e-6 * std::fabs(z) + 1e-12) << f.extension << " " << i << ", " << j;
      }
  }
  EXPECT_EQ(readers, 3);  // .x3p, .gsf, .exr
}

TEST_F(HeightFormats, WritersWithoutAReaderWriteTheirFile) {
  const ZMap map = sampleMap();
  for (const HeightFormat& f : heightFormats()) {
    if (f.read) continue;
    const std::string file = path(std::string("h") + f.extension);
    f.write(map, file, "a title", "");
    EXPECT_GT(std::filesystem::file_size(file), 0u) << f.extension;
  }
}

TEST(HeightFormatTable, LookupIgnoresCaseAndNamesTheExpectedExtensions) {
  ASSERT_NE(findHeightFormat("A/HEIGHTS.GSF"), nullptr);
  EXPECT_STREQ(findHeightFormat("A/HEIGHTS.GSF")->extension, ".gsf");
  EXPECT_EQ(findHeightFormat("h.bmp"), nullptr);
  EXPECT_EQ(findHeightFormat("h"), nullptr);
  EXPECT_EQ(heightExtensions(false), ".x3p, .png, .tif, .tiff, .gsf or .exr");
  EXPECT_EQ(heightExtensions(true), ".x3p, .gsf or .exr");
  EXPECT_EQ(errorOf("h.bmp", false), "h.bmp: expected a file name ending in " +
                                         heightExtensions(false));
  EXPECT_EQ(errorOf("h.png", true),
            "h.png: expected a height map scallop reads: a .x3p, .gsf or .exr file");
  EXPECT_EQ(errorOf("h.png", false), "");
}

}  // namespace
}  // namespace scallop::test
