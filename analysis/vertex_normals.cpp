#include "analysis/vertex_normals.h"

#include <cstdint>
#include <sstream>
#include <unordered_map>

#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

void requireConsistentOrientation(const TriangleMesh& mesh, const std::string& where) {
  // Directed edge (from, to) -> the facet that runs it. A consistently wound surface
  // runs every shared edge once each way.
  std::unordered_map<uint64_t, size_t> runBy;
  runBy.reserve(3 * mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& f = mesh.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const uint64_t key = uint64_t(f[e]) << 32 | f[(e + 1) % 3];
      const auto [it, inserted] = runBy.try_emplace(key, t);
      if (inserted) continue;
      const Vec3& p = mesh.vertices[f[0]];
      std::ostringstream text;
      text.precision(17);
      text << "facet " << t + 1 << " (first corner (" << p.x << ", " << p.y << ", " << p.z
           << ")) is wound the other way from facet " << it->second + 1
           << ", with which it shares an edge: the design's facets must all face outwards "
              "(counter-clockwise seen from outside)";
      throw InputError(where, text.str());
    }
  }
  // A closed surface (every edge run both ways) encloses a volume, whose sign tells its
  // outside: the divergence theorem gives 6 V = sum of a . (b x c) over the facets,
  // positive when they face outwards. Facets that all face inwards would put every
  // vertex normal into the part, where no tool comes from.
  for (const auto& entry : runBy)
    if (!runBy.count(entry.first << 32 | entry.first >> 32)) return;  // open: no inside
  double sixVolume = 0;
  for (const auto& f : mesh.triangles)
    sixVolume += dot(mesh.vertices[f[0]], cross(mesh.vertices[f[1]], mesh.vertices[f[2]]));
  if (sixVolume < 0) {
    throw InputError(where, "the facets of this closed surface all face inwards (its signed "
                            "volume is " + formatNumber(sixVolume / 6) +
                                " mm^3): list each facet's corners the other way round "
                                "(counter-clockwise seen from outside)");
  }
}

std::vector<Vec3> areaWeightedVertexNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> sum(mesh.vertices.size(), Vec3{0, 0, 0});
  for (const auto& f : mesh.triangles) {
    const Vec3& a = mesh.vertices[f[0]];
    const Vec3 n = cross(mesh.vertices[f[1]] - a, mesh.vertices[f[2]] - a);
    for (uint32_t v : f) sum[v] = sum[v] + n;
  }
  for (Vec3& n : sum) {
    const double len = length(n);
    n = len > 0 ? n / len : Vec3{0, 0, 0};
  }
  return sum;
}

}  // namespace scallop
