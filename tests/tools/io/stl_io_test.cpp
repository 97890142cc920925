// STL reading (tools/io/stl_io.h): both encodings told apart by content, welding, and a
// clear error naming the file and triangle or line for every kind of broken file.
#include "tools/io/stl_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "base/input_error.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

// A binary STL built byte by byte (independent of writeStl).
std::string binaryStl(const std::vector<std::array<float, 9>>& tris,
                      const std::string& header = "test", int64_t declared = -1) {
  std::string s = header;
  s.resize(80, ' ');
  const uint32_t n = declared < 0 ? uint32_t(tris.size()) : uint32_t(declared);
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    const float normal[3] = {0, 0, 0};
    s.append(reinterpret_cast<const char*>(normal), 12);
    s.append(reinterpret_cast<const char*>(t.data()), 36);
    s.append(2, '\0');
  }
  return s;
}

const std::vector<std::array<float, 9>> kSquare = {{0, 0, 0, 1, 0, 0, 1, 1, 0},
                                                   {0, 0, 0, 1, 1, 0, 0, 1, 0}};

std::string errorOf(const std::string& bytes) {
  try {
    parseStl(bytes, "part.stl");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Stl, BinaryIsDetectedEvenWhenTheHeaderSaysSolid) {
  StlFormat f;
  const auto soup = parseStl(binaryStl(kSquare, "solid pretending"), "x.stl", &f);
  EXPECT_EQ(f, StlFormat::Binary);
  ASSERT_EQ(soup.size(), 2u);
  EXPECT_EQ(soup[1][1].x, 1.0);
  EXPECT_EQ(soup[1][1].y, 1.0);
}

TEST(Stl, AsciiIsParsedAndWelded) {
  const std::string text =
      "solid sq\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 1 "
      "1 0\n"
      "  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 1 0\n"
      "   vertex 0 1 0\n  endloop\n endfacet\nendsolid sq\n";
  StlFormat f;
  const auto soup = parseStl(text, "a.stl", &f);
  EXPECT_EQ(f, StlFormat::Ascii);
  MeshRepairs rep;
  const TriangleMesh m = meshFromTriangles(soup, &rep);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);  // 6 corners, 4 positions
  EXPECT_EQ(m.normals[0].z, 1.0);
  EXPECT_EQ(rep.degenerateDropped, 0u);
}

TEST(Stl, TruncatedBinaryNamesTheTriangle) {
  std::string b = binaryStl(kSquare);
  b.resize(b.size() - 20);
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("part.stl"), std::string::npos) << e;
  EXPECT_NE(e.find("triangle 2"), std::string::npos) << e;
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
}

TEST(Stl, WrongCountIsAnError) {
  const std::string e = errorOf(binaryStl(kSquare, "x", 1));  // says 1, holds 2
  EXPECT_NE(e.find("declares 1 triangles"), std::string::npos) << e;
}

TEST(Stl, NonFiniteCoordinatesAreNamed) {
  auto bad = kSquare;
  bad[1][4] = std::numeric_limits<float>::quiet_NaN();
  std::string e = errorOf(binaryStl(bad));
  EXPECT_NE(e.find("triangle 2"), std::string::npos) << e;
  EXPECT_NE(e.find("vertex 2"), std::string::npos) << e;
  bad[1][4] = std::numeric_limits<float>::infinity();
  EXPECT_NE(errorOf(binaryStl(bad)).find("non-finite"), std::string::npos);

  e = errorOf("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n");
  EXPECT_NE(e.find("part.stl:5"), std::string::npos) << e;
  EXPECT_NE(e.find("not a finite number"), std::string::npos) << e;
}

TEST(Stl, MalformedAsciiNamesTheLine) {
  std::string e =
      errorOf("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\nvertex 1 1 0\n");
  EXPECT_NE(e.find("part.stl:6"), std::string::npos) << e;  // 'vertex' read as the missing z
  e = errorOf(
      "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 2 "
      "2 2\n");
  EXPECT_NE(e.find("part.stl:7"), std::string::npos) << e;
  EXPECT_NE(e.find("exactly 3 vertices"), std::string::npos) << e;
  e = errorOf("solid x\nfacet normal 0 0 1\nouter loop\n");
  EXPECT_NE(e.find("end of the file"), std::string::npos) << e;
  e = errorOf("solid x\nbanana\n");
  EXPECT_NE(e.find("part.stl:2"), std::string::npos) << e;
}

TEST(Stl, NotAnStlAtAll) {
  EXPECT_NE(errorOf("hello").find("not an STL"), std::string::npos);
  EXPECT_NE(errorOf("").find("not an STL"), std::string::npos);
  EXPECT_NE(errorOf(std::string(200, 'x')).find("not a valid STL"), std::string::npos);
}

TEST(Stl, DegenerateFacetsAreDroppedAndCounted) {
  auto tris = kSquare;
  tris.push_back({0, 0, 0, 1, 1, 0, 2, 2, 0});  // collinear
  tris.push_back({0, 0, 0, 0, 0, 0, 1, 0, 0});  // repeated vertex
  MeshRepairs rep;
  const TriangleMesh m = meshFromTriangles(parseStl(binaryStl(tris), "d.stl"), &rep);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(rep.degenerateDropped, 2u);
  ASSERT_EQ(rep.firstDegenerate.size(), 2u);
  EXPECT_EQ(rep.firstDegenerate[0], 3u);
}

TEST(Stl, WriteAndReadBackBothFormats) {
  const fs::path dir = fs::temp_directory_path() / ("scallop-stl-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const TriangleMesh m = meshFromTriangles({{Vec3{0, 0, 0}, Vec3{2, 0, 0.5}, Vec3{0, 3, 0.25}},
                                            {Vec3{2, 0, 0.5}, Vec3{2, 3, 1}, Vec3{0, 3, 0.25}}});
  for (StlFormat f : {StlFormat::Binary, StlFormat::Ascii}) {
    const std::string p = (dir / (std::string("m.") + toString(f) + ".stl")).string();
    writeStl(m, p, f, "solid-looking header");
    StlInfo info;
    const TriangleMesh back = readStl(p, &info);
    EXPECT_EQ(info.format, f);
    ASSERT_EQ(back.triangles.size(), 2u);
    EXPECT_EQ(back.vertices.size(), 4u);
    for (size_t t = 0; t < 2; ++t)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(back.corners(t)[k], m.corners(t)[k]);  // exact in float
  }
  EXPECT_THROW(readStl((dir / "missing.stl").string()), InputError);
  EXPECT_THROW(readStl(dir.string()), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace scallop
