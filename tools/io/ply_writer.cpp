#include "tools/io/ply_writer.h"

#include <cstdint>
#include <cstring>
#include <ostream>

#include "base/internal_error.h"
#include "tools/io/atomic_file.h"

namespace scallop {

namespace {

// PLY's binary_little_endian values, whatever the host's byte order.
void putLittleEndian(std::ostream& out, uint32_t bits) {
  const char bytes[4] = {char(bits & 0xff), char(bits >> 8 & 0xff), char(bits >> 16 & 0xff),
                         char(bits >> 24 & 0xff)};
  out.write(bytes, 4);
}
void putFloat(std::ostream& out, double v) {
  const float f = float(v);
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  putLittleEndian(out, bits);
}

}  // namespace

void writeVertexValuesPly(const TriangleMesh& mesh, const std::vector<double>& values,
                          const std::string& property, const std::vector<std::string>& comments,
                          const std::string& path) {
  if (values.size() != mesh.vertices.size())
    throw InternalError("writeVertexValuesPly: one value per vertex expected");
  writeStreamAtomically(path, "the PLY mesh", [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\n";
    for (const std::string& c : comments) out << "comment " << c << "\n";
    out << "element vertex " << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty float " << property
        << "\nelement face " << mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Vec3& p = mesh.vertices[v];
      putFloat(out, p.x);
      putFloat(out, p.y);
      putFloat(out, p.z);
      putFloat(out, values[v]);
    }
    for (const auto& f : mesh.triangles) {
      out.put(char(3));
      for (uint32_t i : f) putLittleEndian(out, i);
    }
  });
}

}  // namespace scallop
