// The analytic stand-ins for seed 004's test surfaces (analysis/analytic_surfaces.h):
// the mesh carries the exact heights at its nodes, has about the asked number of
// facets, faces up, and bad specifications are refused naming the field.
#include "analysis/analytic_surfaces.h"

#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"

namespace scallop {
namespace {

TEST(AnalyticSurfaces, NodesCarryTheExactHeightsAndFacetsFaceUp) {
  for (SurfaceShape shape : {SurfaceShape::Plane, SurfaceShape::Dome, SurfaceShape::Bowl,
                             SurfaceShape::Saddle, SurfaceShape::Wave, SurfaceShape::Trough}) {
    SurfaceSpec spec;
    spec.shape = shape;
    spec.sizeX = 80, spec.sizeY = 40, spec.facets = 800;
    const TriangleMesh mesh = makeAnalyticSurface(spec);
    SCOPED_TRACE(toString(shape));
    // 800 facets are 400 cells: 28 x 14 (the sides 2 : 1), two triangles each.
    EXPECT_EQ(mesh.triangles.size(), 2u * 28u * 14u);
    for (const Vec3& v : mesh.vertices) EXPECT_EQ(v.z, surfaceHeight(spec, v.x, v.y));
    for (const Vec3& n : mesh.normals) EXPECT_GT(n.z, 0.0);
  }
}

TEST(AnalyticSurfaces, DefaultHeightIsAFifthOfTheShorterSide) {
  SurfaceSpec spec;
  spec.shape = SurfaceShape::Dome;
  spec.sizeX = 100, spec.sizeY = 50;
  EXPECT_DOUBLE_EQ(spec.heightOrDefault(), 10.0);
  // The dome's top is at the centre (u = v = 0), h above the plane.
  EXPECT_DOUBLE_EQ(surfaceHeight(spec, 50, 25), 10.0);
}

TEST(AnalyticSurfaces, BadSpecificationsNameTheField) {
  EXPECT_EQ(parseSurfaceShape("wave"), SurfaceShape::Wave);
  try {
    parseSurfaceShape("torus", "shape");
    FAIL() << "an unknown shape was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shape"), std::string::npos) << e.what();
  }
  SurfaceSpec spec;
  spec.sizeX = -1;
  EXPECT_THROW(makeAnalyticSurface(spec), InputError);
  spec = SurfaceSpec{};
  spec.facets = 1;
  EXPECT_THROW(makeAnalyticSurface(spec), InputError);
}

}  // namespace
}  // namespace scallop
