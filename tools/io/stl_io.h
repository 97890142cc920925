// STL input and output (binary and ASCII, told apart by content, not by extension).
//
// Reading: a file is binary when its size is exactly 84 + 50 N bytes for the N in its
// header (even if it begins with "solid", as some exporters' binary files do);
// otherwise it is read as ASCII if it begins with "solid". Everything else is an
// error naming the file and the triangle (binary, 1-based) or line (ASCII):
// truncated files, a header count that disagrees with the size, NaN or infinite
// coordinates, malformed ASCII, files with no usable facet. Never a crash.
//
// Documented repairs (counted in StlInfo, never silent):
// - stored facet normals are ignored; each normal is recomputed from the vertices'
//   winding (the STL rule, counter-clockwise seen from outside);
// - identical positions are welded into one vertex (exact, no tolerance);
// - degenerate facets (zero area after welding: repeated or collinear vertices) are
//   dropped.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"

namespace scallop {

enum class StlFormat { Binary, Ascii };
const char* toString(StlFormat format);

struct StlInfo {
  StlFormat format = StlFormat::Binary;
  size_t facets = 0;  // as stored in the file
  MeshRepairs repairs;
};

// The triangles of an STL held in `bytes`; `name` leads every error message.
std::vector<std::array<Vec3, 3>> parseStl(const std::string& bytes, const std::string& name,
                                          StlFormat* format = nullptr);

// Reads, welds and validates; throws InputError(path, ...) on any problem.
TriangleMesh readStl(const std::string& path, StlInfo* info = nullptr);

// Writes atomically (tools/io/atomic_file.h). Binary: `header` (at most 80 bytes, never
// starting with "solid") then float32 normals and vertices. ASCII: "solid NAME" and
// the same float32 values printed exactly (17 digits), so both formats read back alike.
void writeStl(const TriangleMesh& mesh, const std::string& path, StlFormat format,
              const std::string& header);

}  // namespace scallop
