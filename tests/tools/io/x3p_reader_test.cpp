// X3P import (tools/io/x3p_reader.h): scallop's own archives read back (heights in
// float64 metres, so exactly (z * 1e-3) * 1e3 mm), and damaged or foreign archives
// refused with a message naming the file and what is wrong (archives with a member
// missing, damaged or inconsistent: tests/tools/python/test_heights_io.py, which edits them
// with Python's zipfile).
#include "tools/io/x3p_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "raycast/zmap.h"
#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tests/support/sampled_field.h"
#include "tools/io/x3p_writer.h"

namespace scallop::test {
namespace {

ZMap sampleMap() {
  return indexedField(-1.25, 3.5, 7, 5, 0.125, [](int64_t i, int64_t j) {
    return std::sin(0.7 * double(i)) - 0.3 * double(j);
  });
}

std::string readError(const std::string& path) {
  return inputErrorMessage([&] { readHeightsX3p(path); });
}

class X3pReader : public CliFixture {};

TEST_F(X3pReader, ReadsBackWhatTheWriterWrote) {
  const ZMap map = sampleMap();
  const std::string file = path("h.x3p");
  writeHeightsX3p(map, file, "a test");
  const ZMap back = readHeightsX3p(file);
  const GridSpec &g = map.grid(), &b = back.grid();
  ASSERT_EQ(b.nx, g.nx);
  ASSERT_EQ(b.ny, g.ny);
  EXPECT_NEAR(b.spacing, g.spacing, 1e-15);
  EXPECT_NEAR(b.originX, g.originX, 1e-12);
  EXPECT_NEAR(b.originY, g.originY, 1e-12);
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i)
      EXPECT_EQ(back.at(i, j), (map.at(i, j) * 1e-3) * 1e3) << i << ", " << j;
}

TEST_F(X3pReader, RefusesWhatIsNotAnArchiveNamingTheFile) {
  EXPECT_NE(readError(path("none.x3p")).find("none.x3p: cannot open the X3P"), std::string::npos);

  const std::string text = path("text.x3p");
  std::ofstream(text) << "not a zip archive";
  EXPECT_NE(readError(text).find("text.x3p: cannot open the X3P (zip) archive"), std::string::npos);
}

}  // namespace
}  // namespace scallop::test
