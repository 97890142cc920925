// The design mesh with a value per vertex as a binary little-endian PLY (ParaView and
// MeshLab open it): vertices x, y, z (float, mm) and one float property per vertex
// (NaN where the value is undefined), faces as vertex index lists (uchar count, int
// indices). Written atomically (atomic_file.h).
#pragma once

#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"

namespace scallop {

// `values` has one entry per vertex of `mesh`; `property` names it in the header
// ("deviation"); `comment` lines (no newlines) go in the header.
void writeVertexValuesPly(const TriangleMesh& mesh, const std::vector<double>& values,
                          const std::string& property, const std::vector<std::string>& comments,
                          const std::string& path);

}  // namespace scallop
