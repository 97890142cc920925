// Height image writers and readers (tools/io/height_images.h) and atomic output
// (tools/io/atomic_file.h): values, row order, metadata, file layout, failure cleanup.
#include "tools/io/height_images.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "raycast/zmap.h"
#include "tests/support/sampled_field.h"
#include "tools/io/atomic_file.h"
#include "tools/render/preview_png.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

// Distinct in i and j and not separable, so a transposed or flipped file is caught.
double knownHeight(int64_t i, int64_t j) {
  return -0.5 + 0.1 * i - 0.01 * j + 0.001 * i * j;
}

ZMap makeMap() {
  return indexedField(-3.25, 1.5, 7, 5, 0.125, knownHeight);
}

std::vector<unsigned char> readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

float floatLE(const unsigned char* p) {
  uint32_t bits =
      uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

struct GsfFile {
  std::map<std::string, std::string> keys;
  size_t textEnd = 0;    // offset of the first NUL
  size_t dataStart = 0;  // offset of the first float
  std::vector<unsigned char> bytes;
};

// An independent, minimal parse of the layout the GSF documentation describes.
GsfFile parseGsf(const fs::path& p) {
  GsfFile f;
  f.bytes = readBytes(p);
  const std::string all(f.bytes.begin(), f.bytes.end());
  f.textEnd = all.find('\0');
  f.dataStart = f.textEnd;
  while (f.dataStart < all.size() && all[f.dataStart] == '\0' && f.dataStart - f.textEnd < 4)
    ++f.dataStart;
  std::string text = all.substr(0, f.textEnd);
  size_t pos = text.find('\n') + 1;
  while (pos < text.size()) {
    const size_t end = text.find('\n', pos);
    const std::string line = text.substr(pos, end - pos);
    const size_t eq = line.find(" = ");
    if (eq != std::string::npos) f.keys[line.substr(0, eq)] = line.substr(eq + 3);
    pos = end + 1;
  }
  return f;
}

bool hasTempFiles(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

class HeightImagesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scallop-images-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(HeightImagesTest, ExrRoundTripsValuesGridAndRowOrder) {
  const ZMap map = makeMap();
  const std::string path = file("heights.exr");
  writeHeightsExr(map, path);

  const ZMap back = readHeightsExr(path);
  EXPECT_EQ(back.nx(), map.nx());
  EXPECT_EQ(back.ny(), map.ny());
  EXPECT_EQ(back.grid().originX, map.grid().originX);
  EXPECT_EQ(back.grid().originY, map.grid().originY);
  EXPECT_EQ(back.grid().spacing, map.grid().spacing);
  for (int64_t j = 0; j < map.ny(); ++j)
    for (int64_t i = 0; i < map.nx(); ++i)
      EXPECT_EQ(back.at(i, j), double(float(map.at(i, j)))) << "cell " << i << "," << j;

  // The file itself, read without our reader: one float channel "Z", row 0 = largest y.
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(in->format_name(), std::string("openexr"));
  ASSERT_EQ(spec.nchannels, 1);
  EXPECT_EQ(spec.channelnames[0], "Z");
  EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(spec.width, 7);
  EXPECT_EQ(spec.height, 5);
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
  EXPECT_FALSE(spec.get_string_attribute("ImageDescription").empty());
  std::vector<float> pixels(size_t(spec.width * spec.height));
  ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, pixels.data()));
  for (int row = 0; row < spec.height; ++row)
    for (int i = 0; i < spec.width; ++i)
      EXPECT_EQ(pixels[size_t(row * spec.width + i)], float(knownHeight(i, map.ny() - 1 - row)))
          << "image row " << row << " column " << i;
}

TEST_F(HeightImagesTest, GsfHeaderLayoutAndValues) {
  const ZMap map = makeMap();
  const std::string path = file("heights.gsf");
  writeHeightsGsf(map, path, "Raster x");

  const GsfFile f = parseGsf(path);
  const std::string magic = "Gwyddion Simple Field 1.0\n";
  ASSERT_GE(f.bytes.size(), magic.size());
  EXPECT_EQ(std::string(f.bytes.begin(), f.bytes.begin() + long(magic.size())), magic);
  EXPECT_EQ(f.keys.at("XRes"), "7");
  EXPECT_EQ(f.keys.at("YRes"), "5");
  EXPECT_DOUBLE_EQ(std::stod(f.keys.at("XReal")), 7 * 0.125e-3);
  EXPECT_DOUBLE_EQ(std::stod(f.keys.at("YReal")), 5 * 0.125e-3);
  EXPECT_DOUBLE_EQ(std::stod(f.keys.at("XOffset")), -3.25e-3);
  EXPECT_DOUBLE_EQ(std::stod(f.keys.at("YOffset")), 1.5e-3);
  EXPECT_EQ(f.keys.at("XYUnits"), "m");
  EXPECT_EQ(f.keys.at("ZUnits"), "m");
  EXPECT_EQ(f.keys.at("Title"), "Raster x");

  EXPECT_EQ(f.dataStart % 4, 0u);
  EXPECT_GE(f.dataStart - f.textEnd, 1u);
  EXPECT_LE(f.dataStart - f.textEnd, 4u);
  ASSERT_EQ(f.bytes.size(), f.dataStart + 4 * 7 * 5);
  // Float32 little-endian metres, first row = largest y.
  for (int row = 0; row < 5; ++row)
    for (int i = 0; i < 7; ++i)
      EXPECT_EQ(floatLE(&f.bytes[f.dataStart + 4 * size_t(row * 7 + i)]),
                float(knownHeight(i, 4 - row) * 1e-3))
          << "row " << row << " column " << i;

  const ZMap back = readHeightsGsf(path);
  ASSERT_EQ(back.nx(), 7);
  ASSERT_EQ(back.ny(), 5);
  EXPECT_NEAR(back.grid().spacing, 0.125, 1e-15);
  EXPECT_NEAR(back.grid().originX, -3.25, 1e-15);
  EXPECT_NEAR(back.grid().originY, 1.5, 1e-15);
  for (int64_t j = 0; j < 5; ++j)
    for (int64_t i = 0; i < 7; ++i) {
      const double h = knownHeight(i, j);
      EXPECT_NEAR(back.at(i, j), h, std::abs(h) * 1.2e-7 + 1e-12) << "cell " << i << "," << j;
    }
}

TEST_F(HeightImagesTest, GsfPaddingIsOneToFourNulsForEveryHeaderLength) {
  const ZMap map = makeMap();
  std::set<size_t> paddings;
  for (int n = 0; n < 8; ++n) {
    const std::string path = file("t" + std::to_string(n) + ".gsf");
    writeHeightsGsf(map, path, std::string(size_t(n), 'a'));
    const GsfFile f = parseGsf(path);
    EXPECT_EQ(f.dataStart % 4, 0u) << "title length " << n;
    EXPECT_EQ(f.bytes.size(), f.dataStart + 4 * 7 * 5) << "title length " << n;
    paddings.insert(f.dataStart - f.textEnd);
    EXPECT_EQ(readHeightsGsf(path).at(3, 2), double(float(knownHeight(3, 2) * 1e-3)) * 1e3);
  }
  EXPECT_EQ(paddings, (std::set<size_t>{1, 2, 3, 4}));
}

TEST_F(HeightImagesTest, GsfReaderRejectsTruncatedFile) {
  const std::string path = file("heights.gsf");
  writeHeightsGsf(makeMap(), path, "t");
  fs::resize_file(path, fs::file_size(path) - 1);
  EXPECT_THROW(readHeightsGsf(path), InputError);
}

TEST_F(HeightImagesTest, OiiotoolAcceptsExr) {
  if (std::system("command -v oiiotool > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "oiiotool not on PATH (Debian package openimageio-tools)";
  const std::string path = file("heights.exr");
  writeHeightsExr(makeMap(), path);
  EXPECT_EQ(std::system(("oiiotool --stats '" + path + "' > /dev/null 2>&1").c_str()), 0);
}

TEST_F(HeightImagesTest, PreviewIsRgbAndLargerThanTheMap) {
  const ZMap map = makeMap();
  const std::string path = file("preview.png");
  PreviewOptions options;
  options.title = "Test 1.5 um";
  writePreviewPng(map, path, options);

  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(in->format_name(), std::string("png"));
  EXPECT_EQ(spec.nchannels, 3);
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
  EXPECT_GT(spec.width, map.nx());
  EXPECT_GT(spec.height, map.ny());
  EXPECT_GE(spec.width, options.minPixels);  // the 7 x 5 map was enlarged

  std::vector<uint8_t> rgb(size_t(spec.width * spec.height * 3));
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb.data()));
  std::set<uint32_t> colours;
  for (size_t p = 0; p < rgb.size(); p += 3)
    colours.insert(uint32_t(rgb[p]) << 16 | uint32_t(rgb[p + 1]) << 8 | rgb[p + 2]);
  EXPECT_GT(colours.size(), 30u) << "expected a colour-mapped picture, not a blank image";
}

TEST_F(HeightImagesTest, PreviewOfFlatAndLargeMaps) {
  GridSpec flatGrid;
  flatGrid.spacing = 0.01;
  flatGrid.nx = 30;
  flatGrid.ny = 20;
  writePreviewPng(ZMap(flatGrid, -0.25), file("flat.png"));

  GridSpec wide = flatGrid;
  wide.nx = 5000;
  wide.ny = 120;
  ZMap big(wide, 0.0);
  for (int64_t j = 0; j < wide.ny; ++j)
    for (int64_t i = 0; i < wide.nx; ++i) big.at(i, j) = 0.002 * std::cos(double(i) * 0.05);
  PreviewOptions options;
  options.maxPixels = 800;
  writePreviewPng(big, file("big.png"), options);

  for (const char* name : {"flat.png", "big.png"}) {
    auto in = OIIO::ImageInput::open(file(name));
    ASSERT_TRUE(in) << name << ": " << OIIO::geterror();
    EXPECT_EQ(in->spec().nchannels, 3) << name;
    if (std::string(name) == "big.png") {
      EXPECT_LT(in->spec().width, 800 + 400) << "the map part is limited to maxPixels";
      EXPECT_GT(in->spec().width, 400);
    }
  }
}

TEST_F(HeightImagesTest, MissingParentFolderThrowsNamingThePath) {
  const ZMap map = makeMap();
  for (const char* name : {"heights.exr", "heights.gsf", "preview.png"}) {
    const std::string path = file(std::string("missing/") + name);
    try {
      if (std::string(name) == "heights.exr") writeHeightsExr(map, path);
      if (std::string(name) == "heights.gsf") writeHeightsGsf(map, path, "t");
      if (std::string(name) == "preview.png") writePreviewPng(map, path);
      ADD_FAILURE() << "no exception for " << path;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), path);
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(std::strerror(ENOENT)), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(HeightImagesTest, FailedRenameLeavesNoTemporaryFile) {
  // The target is a non-empty folder, so the final rename fails after the whole
  // image was written to the temporary file.
  const std::string path = file("heights.exr");
  fs::create_directories(fs::path(path) / "keep");
  try {
    writeHeightsExr(makeMap(), path);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(hasTempFiles(dir_));
  EXPECT_TRUE(fs::is_directory(fs::path(path) / "keep"));
}

TEST_F(HeightImagesTest, ReadOnlyFolderThrowsAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "permissions do not apply to root";
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string path = file("heights.gsf");
  EXPECT_THROW(writeHeightsGsf(makeMap(), path, "t"), InputError);
  EXPECT_THROW(ensureWritableDirectory(dir_.string()), InputError);
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(HeightImagesTest, AtomicFileWithoutCommitLeavesNoFile) {
  const std::string path = file("out.txt");
  std::string temp;
  {
    AtomicFile f(path);
    temp = f.tempPath();
    EXPECT_EQ(fs::path(temp).parent_path(), fs::path(path).parent_path());
    EXPECT_EQ(fs::path(temp).filename().string()[0], '.');
    std::ofstream(temp) << "partial";
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(HeightImagesTest, AtomicWriteReplacesOnlyOnSuccess) {
  const std::string path = file("out.txt");
  std::ofstream(path) << "old";
  auto content = [&] {
    const auto b = readBytes(path);
    return std::string(b.begin(), b.end());
  };

  EXPECT_THROW(writeFileAtomically(path,
                                   [](const std::string& temp) {
                                     std::ofstream(temp) << "half";
                                     throw std::runtime_error("writer failed");
                                   }),
               std::runtime_error);
  EXPECT_EQ(content(), "old");
  EXPECT_FALSE(hasTempFiles(dir_));

  writeFileAtomically(path, [](const std::string& temp) { std::ofstream(temp) << "new"; });
  EXPECT_EQ(content(), "new");
  EXPECT_FALSE(hasTempFiles(dir_));
}

TEST_F(HeightImagesTest, EnsureWritableDirectory) {
  const fs::path nested = dir_ / "a" / "b";
  ensureWritableDirectory(nested.string());
  EXPECT_TRUE(fs::is_directory(nested));
  EXPECT_TRUE(fs::is_empty(nested)) << "the probe file must be removed";
  ensureWritableDirectory(nested.string());  // existing folder is fine

  const std::string notDir = file("plain");
  std::ofstream(notDir) << "x";
  try {
    ensureWritableDirectory(notDir);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), notDir);
  }
  try {
    ensureWritableDirectory(notDir + "/sub");
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), notDir + "/sub");
    EXPECT_NE(std::string(e.what()).find(notDir + "/sub"), std::string::npos);
  }
}

}  // namespace
}  // namespace scallop
