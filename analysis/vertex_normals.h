// Outward vertex normals of a design mesh (CONVENTIONS.md "Normal deviation on a design
// surface"): the area-weighted mean of the adjacent facets' normals, after checking
// that the facets agree on which side is outside.
#pragma once

#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"

namespace scallop {

// Throws InputError(where, ...) naming the first facet (1-based in the welded mesh, with
// its first corner) that runs an edge in the same direction as an earlier facet: two
// facets sharing an edge face opposite sides of the surface. Facets of an edge shared
// by more than two are compared with the first only. A closed surface (every edge shared
// by two facets) whose facets all face inwards (negative signed volume) is refused too.
void requireConsistentOrientation(const TriangleMesh& mesh, const std::string& where);

// Per vertex: the sum of (b - a) x (c - a) over its facets (twice the area times the unit
// normal), normalised; (0, 0, 0) where the sum vanishes (no facet, or facets that cancel).
std::vector<Vec3> areaWeightedVertexNormals(const TriangleMesh& mesh);

}  // namespace scallop
