// Height files checked with programs nobody here wrote: Gwyddion (Debian's `gwyddion`:
// `gwyddion --convert-to-gwy` loads a file with its own GSF or X3P module and saves
// what it read as a .gwy, whose documented serialisation we parse here;
// `gwyddion-thumbnailer` reports size and extent) and OpenImageIO's `oiiotool --stats`.
// Each check compares size, extent, offsets and values with what was written, and
// skips only when the program is not installed (scripts/install-deps.sh installs them).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "raycast/zmap.h"
#include "tests/support/cli_harness.h"
#include "tests/support/sampled_field.h"
#include "tools/io/height_images.h"
#include "tools/io/x3p_writer.h"

namespace scallop::test {
namespace {

bool installed(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// A map with distinct, non-separable values and a non-zero origin, so that a
// transposed, flipped or shifted reading is caught.
ZMap knownMap() {
  return indexedField(-3.25, 1.5, 9, 6, 0.125, [](int64_t i, int64_t j) {
    return -0.5 + 0.01 * i - 0.003 * j + 1e-4 * i * j;
  });
}

// The first GwyDataField of a .gwy file (Gwyddion user guide, "GWY file format"):
// "GWYP", then an object = name NUL, uint32 size, components; a component = name NUL,
// a type letter and the value (b c i q d s o; upper case: uint32 count + array).
struct GwyField {
  int xres = 0, yres = 0;
  double xreal = 0, yreal = 0, xoff = 0, yoff = 0;
  std::string unitXy, unitZ;
  std::vector<double> data;
};

class GwyParser {
 public:
  explicit GwyParser(std::string bytes) : b_(std::move(bytes)) {}
  bool parse(GwyField& field) {
    if (b_.compare(0, 4, "GWYP") != 0) return false;
    p_ = 4;
    object("", field);
    return found_;
  }

 private:
  std::string cstr() {
    const size_t end = b_.find('\0', p_);
    std::string s = b_.substr(p_, end - p_);
    p_ = end + 1;
    return s;
  }
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, b_.data() + p_, sizeof(T));  // little-endian, as this machine
    p_ += sizeof(T);
    return v;
  }
  void object(const std::string& key, GwyField& field) {
    const std::string type = cstr();
    const uint32_t size = get<uint32_t>();
    const size_t end = p_ + size;
    const bool isField = type == "GwyDataField" && !found_;
    while (p_ < end) component(isField, field);
    if (isField) found_ = true;
    (void)key;
  }
  void component(bool inField, GwyField& f) {
    const std::string name = cstr();
    const char type = b_[p_++];
    switch (type) {
      case 'b':
      case 'c':
        p_ += 1;
        break;
      case 'i': {
        const int32_t v = get<int32_t>();
        if (inField && name == "xres") f.xres = v;
        if (inField && name == "yres") f.yres = v;
        break;
      }
      case 'q':
        p_ += 8;
        break;
      case 'd': {
        const double v = get<double>();
        if (!inField) break;
        if (name == "xreal") f.xreal = v;
        if (name == "yreal") f.yreal = v;
        if (name == "xoff") f.xoff = v;
        if (name == "yoff") f.yoff = v;
        break;
      }
      case 's': {
        const std::string s = cstr();
        if (name == "unitstr") lastUnit_ = s;
        break;
      }
      case 'o': {
        lastUnit_.clear();
        GwyField ignored;
        object(name, inField ? ignored : f);
        if (inField && name == "si_unit_xy") f.unitXy = lastUnit_;
        if (inField && name == "si_unit_z") f.unitZ = lastUnit_;
        break;
      }
      case 'D': {
        const uint32_t n = get<uint32_t>();
        if (inField && name == "data") {
          f.data.resize(n);
          std::memcpy(f.data.data(), b_.data() + p_, 8 * size_t(n));
        }
        p_ += 8 * size_t(n);
        break;
      }
      case 'C':
        p_ += get<uint32_t>();
        break;
      case 'I':
        p_ += 4 * size_t(get<uint32_t>());
        break;
      case 'Q':
        p_ += 8 * size_t(get<uint32_t>());
        break;
      case 'S': {
        for (uint32_t n = get<uint32_t>(); n > 0; --n) cstr();
        break;
      }
      case 'O': {
        for (uint32_t n = get<uint32_t>(); n > 0; --n) {
          GwyField ignored;
          object(name, inField ? ignored : f);
        }
        break;
      }
      default:
        p_ = b_.size();  // unknown type: stop
    }
  }
  std::string b_;
  size_t p_ = 0;
  bool found_ = false;
  std::string lastUnit_;
};

class ExternalReaders : public CliFixture {
 protected:
  // What Gwyddion read from `file`, through its .gwy export.
  GwyField gwyddionReads(const std::string& file) {
    const std::string gwy = path("read.gwy");
    const std::string cmd =
        "gwyddion --convert-to-gwy=" + gwy + " " + file + " >/dev/null 2>" + path("gwy.err");
    EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(path("gwy.err"));
    GwyField f;
    EXPECT_TRUE(GwyParser(slurp(gwy)).parse(f)) << "no GwyDataField in " << gwy;
    return f;
  }
  // `write`s `map` to `name`, has Gwyddion read it and checks the size and extent it saw.
  template <class Write>
  GwyField writtenAndRead(const ZMap& map, const std::string& name, Write write) {
    write(map, path(name), "external reader check");
    const GwyField f = gwyddionReads(path(name));
    const GridSpec& g = map.grid();
    EXPECT_EQ(f.xres, g.nx);
    EXPECT_EQ(f.yres, g.ny);
    EXPECT_NEAR(f.xreal, g.nx * g.spacing * 1e-3, 1e-18);
    EXPECT_NEAR(f.yreal, g.ny * g.spacing * 1e-3, 1e-18);
    return f;
  }
};

TEST_F(ExternalReaders, GwyddionReadsTheGsfAsWritten) {
  if (!installed("gwyddion")) GTEST_SKIP() << "gwyddion is not installed (scripts/install-deps.sh)";
  const ZMap map = knownMap();
  const GridSpec& g = map.grid();
  const GwyField f = writtenAndRead(
      map, "h.gsf", [](const ZMap& m, const std::string& p, const std::string& title) {
        writeHeightsGsf(m, p, title);
      });
  EXPECT_NEAR(f.xoff, g.originX * 1e-3, 1e-18);
  EXPECT_NEAR(f.yoff, g.originY * 1e-3, 1e-18);
  EXPECT_EQ(f.unitXy, "m");
  EXPECT_EQ(f.unitZ, "m");
  ASSERT_EQ(f.data.size(), size_t(g.cells()));
  // Gwyddion's row 0 is the top of the picture: our largest y. Values are the float32
  // of metres, exactly.
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int64_t row = 0; row < g.ny; ++row)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double z = double(float(map.at(i, g.ny - 1 - row) * 1e-3));
      EXPECT_EQ(f.data[size_t(row * g.nx + i)], z) << row << " " << i;
      lo = std::min(lo, f.data[size_t(row * g.nx + i)]);
      hi = std::max(hi, f.data[size_t(row * g.nx + i)]);
    }
  EXPECT_NEAR(lo, map.minHeight() * 1e-3, 1e-10);
  EXPECT_NEAR(hi, map.maxHeight() * 1e-3, 1e-10);
}

TEST_F(ExternalReaders, GwyddionReadsTheX3pAsWritten) {
  if (!installed("gwyddion")) GTEST_SKIP() << "gwyddion is not installed (scripts/install-deps.sh)";
  const ZMap map = knownMap();
  const GridSpec& g = map.grid();
  const GwyField f = writtenAndRead(map, "h.x3p", writeHeightsX3p);
  ASSERT_EQ(f.data.size(), size_t(g.cells()));
  // X3P holds float64 metres in ZMap order (first row = smallest y): exact doubles.
  for (size_t k = 0; k < f.data.size(); ++k) EXPECT_EQ(f.data[k], map.heights()[k] * 1e-3) << k;
}

TEST_F(ExternalReaders, GwyddionThumbnailerSeesSizeAndExtent) {
  if (!installed("gwyddion-thumbnailer"))
    GTEST_SKIP() << "gwyddion-thumbnailer is not installed (scripts/install-deps.sh)";
  const ZMap map = knownMap();
  writeHeightsGsf(map, path("h.gsf"), "thumbnail check");
  const std::string cmd = "gwyddion-thumbnailer gnome2 256 " + path("h.gsf") + " " +
                          path("thumb.png") + " 2>" + path("thumb.err");
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(path("thumb.err"));
  // PNG tEXt chunks "key NUL value" (the thumbnail standard's Thumb:: keys).
  const std::string png = slurp(path("thumb.png"));
  std::map<std::string, std::string> text;
  for (size_t p = 8; p + 12 <= png.size();) {
    const uint32_t n = uint32_t(uint8_t(png[p])) << 24 | uint32_t(uint8_t(png[p + 1])) << 16 |
                       uint32_t(uint8_t(png[p + 2])) << 8 | uint32_t(uint8_t(png[p + 3]));
    if (png.compare(p + 4, 4, "tEXt") == 0) {
      const std::string chunk = png.substr(p + 8, n);
      const size_t nul = chunk.find('\0');
      text[chunk.substr(0, nul)] = chunk.substr(nul + 1);
    }
    p += 12 + n;
  }
  EXPECT_EQ(text["Thumb::Image::Width"], "9");
  EXPECT_EQ(text["Thumb::Image::Height"], "6");
  // "1.1×0.75 mm" (rounded by Gwyddion): 9 x 0.125 = 1.125 and 6 x 0.125 = 0.75 mm.
  std::smatch m;
  const std::string size = text["Thumb::X-Gwyddion::RealSize"];
  ASSERT_TRUE(std::regex_search(size, m, std::regex(R"(([0-9.]+)\D+([0-9.]+) mm)"))) << size;
  EXPECT_NEAR(std::stod(m[1]), 1.125, 0.05) << size;
  EXPECT_NEAR(std::stod(m[2]), 0.75, 0.05) << size;
}

TEST_F(ExternalReaders, OiiotoolStatsOfTheExr) {
  if (!installed("oiiotool")) GTEST_SKIP() << "oiiotool is not installed (openimageio-tools)";
  const ZMap map = knownMap();
  writeHeightsExr(map, path("h.exr"));
  const std::string cmd = "oiiotool --stats -v " + path("h.exr") + " >" + path("stats.txt");
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string out = slurp(path("stats.txt"));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"((\d+) x\s+(\d+), 1 channel, float)"))) << out;
  EXPECT_EQ(std::stoi(m[1]), 9);
  EXPECT_EQ(std::stoi(m[2]), 6);
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(Stats Min: (\S+))"))) << out;
  EXPECT_NEAR(std::stod(m[1]), map.minHeight(), 1e-6);  // oiiotool prints 6 digits
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(Stats Max: (\S+))"))) << out;
  EXPECT_NEAR(std::stod(m[1]), map.maxHeight(), 1e-6);
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(scallop:spacing_mm: (\S+))"))) << out;
  EXPECT_DOUBLE_EQ(std::stod(m[1]), 0.125);
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(scallop:origin_x: (\S+))"))) << out;
  EXPECT_DOUBLE_EQ(std::stod(m[1]), -3.25);
}

// The 16-bit exports, read by oiiotool: size, the full 0..65535 range, and the height
// scale in the metadata giving back the map's extremes.
TEST_F(ExternalReaders, OiiotoolReadsThe16BitExportsAndTheirScale) {
  if (!installed("oiiotool")) GTEST_SKIP() << "oiiotool is not installed (openimageio-tools)";
  const ZMap map = knownMap();
  writeHeightsGsf(map, path("h.gsf"), "16-bit");
  for (const char* name : {"h.png", "h.tif"}) {
    SCOPED_TRACE(name);
    const CliRun r = run("export " + path("h.gsf") + " --to " + path(name));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string cmd = "oiiotool --stats -v " + path(name) + " >" + path("stats.txt");
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string out = slurp(path("stats.txt"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(out, m, std::regex(R"((\d+) x\s+(\d+), 1 channel, uint16)")))
        << out;
    EXPECT_EQ(std::stoi(m[1]), 9);
    EXPECT_EQ(std::stoi(m[2]), 6);
    ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(Stats Min: (\d+) \(of 65535\))"))) << out;
    EXPECT_EQ(std::stoi(m[1]), 0);
    ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(Stats Max: (\d+) \(of 65535\))"))) << out;
    EXPECT_EQ(std::stoi(m[1]), 65535);
    ASSERT_TRUE(std::regex_search(
        out, m, std::regex(R"(z_offset_mm = ([-0-9.e]+); z_scale_mm = ([-0-9.e]+))")))
        << out;
    const double offset = std::stod(m[1]), scale = std::stod(m[2]);
    // The GSF holds float32 heights: the extremes come back to float precision.
    EXPECT_NEAR(offset, map.minHeight(), 1e-7);
    EXPECT_NEAR(offset + 65535 * scale, map.maxHeight(), 1e-7);
  }
}

}  // namespace
}  // namespace scallop::test
