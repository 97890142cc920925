// X3P export (tools/io/x3p_writer.h) read back with `unzip` and `md5sum`, not with our
// own code: the archive's members, main.xml's ISO 5436-2 structure and numbers, the
// data's size and values, and both MD5 checksums. MD5 itself against RFC 1321's
// test suite (appendix A.5).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <regex>
#include <string>

#include "tests/support/cli_harness.h"
#include "raycast/zmap.h"
#include "base/input_error.h"
#include "tools/io/md5.h"
#include "tools/io/x3p_writer.h"

namespace scallop::test {
namespace {

TEST(Md5, Rfc1321TestSuite) {
  EXPECT_EQ(md5Hex(""), "d41d8cd98f00b204e9800998ecf8427e");
  EXPECT_EQ(md5Hex("a"), "0cc175b9c0f1b6a831c399e269772661");
  EXPECT_EQ(md5Hex("abc"), "900150983cd24fb0d6963f7d28e17f72");
  EXPECT_EQ(md5Hex("message digest"), "f96b697d7cb7938d525a2f31aaf161d0");
  EXPECT_EQ(md5Hex("abcdefghijklmnopqrstuvwxyz"), "c3fcd3d76192e4007dfb496cca67e13b");
  EXPECT_EQ(md5Hex("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"),
            "d174ab98d277d9f5a5611c2c9f419d9f");
  EXPECT_EQ(md5Hex("1234567890123456789012345678901234567890123456789012345678901234567890123456"
                   "7890"),
            "57edf4a22be3c955ac49da2e2107b67a");
  // Fed in pieces that straddle the 64-byte blocks, the same digest.
  Md5 parts;
  const std::string text(1000, 'x');
  for (size_t at = 0; at < text.size(); at += 37)
    parts.update(text.data() + at, std::min<size_t>(37, text.size() - at));
  EXPECT_EQ(parts.hexDigest(), md5Hex(text));
}

class X3p : public CliFixture {
 protected:
  std::string shell(const std::string& cmd) {
    const std::string out = path(".shell.out");
    EXPECT_EQ(std::system((cmd + " >" + out + " 2>&1").c_str()), 0) << cmd << slurp(out);
    return slurp(out);
  }
};

std::string element(const std::string& xml, const std::string& pathRegex) {
  std::smatch m;
  if (!std::regex_search(xml, m, std::regex(pathRegex))) return "<missing " + pathRegex + ">";
  return m[1];
}

TEST_F(X3p, ArchiveMatchesIso5436Part2) {
  if (std::system("command -v unzip >/dev/null && command -v md5sum >/dev/null") != 0)
    GTEST_SKIP() << "unzip or md5sum is not installed";
  GridSpec g;
  g.originX = 2.0;
  g.originY = -1.0;
  g.spacing = 0.004;
  g.nx = 13;
  g.ny = 7;
  ZMap map(g, 0.0);
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) map.at(i, j) = -0.25 + 1e-3 * i - 2e-4 * j * j;
  const std::string file = path("h.x3p");
  writeHeightsX3p(map, file, "a <comment> & more");

  const std::string listing = shell("unzip -l " + file);
  for (const char* member : {"main.xml", "bindata/data.bin", "md5checksum.hex"})
    EXPECT_NE(listing.find(member), std::string::npos) << member << "\n" << listing;

  shell("cd " + dir_.string() + " && unzip -o -q h.x3p");
  const std::string xml = slurp(path("main.xml"));
  EXPECT_NE(xml.find("<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\""),
            std::string::npos);
  EXPECT_EQ(element(xml, "<Record1>\\s*<Revision>([^<]*)</Revision>"), "ISO5436 - 2000");
  EXPECT_EQ(element(xml, "<FeatureType>([^<]*)</FeatureType>"), "SUR");
  const std::string axis =
      "<{}>\\s*<AxisType>(\\w)</AxisType>\\s*<DataType>(\\w)</DataType>\\s*"
      "<Increment>([^<]*)</Increment>\\s*<Offset>([^<]*)</Offset>";
  for (const auto& [name, type, increment, offset] :
       {std::tuple<std::string, std::string, double, double>{"CX", "I", 4e-6, 2.002e-3},
        {"CY", "I", 4e-6, -0.998e-3},
        {"CZ", "A", 1.0, 0.0}}) {
    std::smatch m;
    const std::string re = std::regex_replace(axis, std::regex("\\{\\}"), name);
    ASSERT_TRUE(std::regex_search(xml, m, std::regex(re))) << name;
    EXPECT_EQ(m[1], type) << name;
    EXPECT_EQ(m[2], "D") << name;
    EXPECT_NEAR(std::stod(m[3]), increment, 1e-18) << name;
    EXPECT_NEAR(std::stod(m[4]), offset, 1e-15) << name;
  }
  EXPECT_EQ(element(xml, "<SizeX>(\\d+)</SizeX>"), "13");
  EXPECT_EQ(element(xml, "<SizeY>(\\d+)</SizeY>"), "7");
  EXPECT_EQ(element(xml, "<SizeZ>(\\d+)</SizeZ>"), "1");
  EXPECT_EQ(element(xml, "<PointDataLink>([^<]*)</PointDataLink>"), "bindata/data.bin");
  EXPECT_EQ(element(xml, "<ChecksumFile>([^<]*)</ChecksumFile>"), "md5checksum.hex");
  EXPECT_EQ(element(xml, "<Comment>([^<]*)</Comment>"), "a &lt;comment&gt; &amp; more");
  // Record order 1, 2, 3, 4.
  EXPECT_LT(xml.find("<Record1>"), xml.find("<Record2>"));
  EXPECT_LT(xml.find("<Record2>"), xml.find("<Record3>"));
  EXPECT_LT(xml.find("<Record3>"), xml.find("<Record4>"));

  // Checksums by md5sum: of the data (in main.xml) and of main.xml (in the .hex file).
  const std::string dataSum = shell("md5sum " + path("bindata/data.bin")).substr(0, 32);
  EXPECT_EQ(element(xml, "<MD5ChecksumPointData>([0-9a-f]{32})</MD5ChecksumPointData>"), dataSum);
  const std::string xmlSum = shell("md5sum " + path("main.xml")).substr(0, 32);
  EXPECT_EQ(slurp(path("md5checksum.hex")).substr(0, 32), xmlSum);

  // The data: SizeX * SizeY little-endian float64 metres, x fastest, first row = smallest y.
  const std::string data = slurp(path("bindata/data.bin"));
  ASSERT_EQ(data.size(), size_t(8 * 13 * 7));
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      uint64_t bits = 0;
      for (int b = 0; b < 8; ++b)
        bits |= uint64_t(uint8_t(data[size_t(8 * (j * g.nx + i) + b)])) << (8 * b);
      double v;
      std::memcpy(&v, &bits, 8);
      EXPECT_EQ(v, map.at(i, j) * 1e-3) << i << " " << j;
    }
}

TEST_F(X3p, UnwritableTargetLeavesNothing) {
  GridSpec g;
  g.spacing = 1;
  g.nx = g.ny = 2;
  const ZMap map(g, 0.0);
  EXPECT_THROW(writeHeightsX3p(map, path("no/such/dir/h.x3p"), ""), InputError);
  EXPECT_THROW(writeHeightsX3p(ZMap(), path("empty.x3p"), ""), InputError);
  EXPECT_FALSE(fs::exists(path("empty.x3p")));
}

}  // namespace
}  // namespace scallop::test
