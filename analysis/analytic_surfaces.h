// Analytic test surfaces for seed 004's strategy. The seed's three models ("different
// combinations of convex, concave, and saddle", §2, Figure 1) were made in CAD software
// and not published; these analytic height fields stand in for them, faceted on a
// regular grid at a chosen density:
//   plane   z = 0
//   dome    z = h (1 - (u^2 + v^2) / 2)          convex
//   bowl    z = h (u^2 + v^2) / 2                concave
//   saddle  z = h (1 + u^2 - v^2) / 2            saddle (concave along x, convex along y)
//   wave    z = h (1 + sin(1.5 pi u) cos(pi v)) / 2   mixed convex, concave and saddle
//   trough  z = 0 except a cylindrical groove of radius r and depth d = min(h, r) along
//           y at x = X/2: z = (r - d) - sqrt(r^2 - (x - X/2)^2) there
// with u = 2x/X - 1, v = 2y/Y - 1 over [0, X] x [0, Y] (mm), h the height.
#pragma once

#include <cstdint>
#include <string>

#include "analysis/triangle_mesh.h"

namespace scallop {

enum class SurfaceShape { Plane, Dome, Bowl, Saddle, Wave, Trough };
const char* toString(SurfaceShape shape);
// Throws InputError naming `field` for an unknown name.
SurfaceShape parseSurfaceShape(const std::string& name, const std::string& field = "--shape");

struct SurfaceSpec {
  SurfaceShape shape = SurfaceShape::Dome;
  double sizeX = 100, sizeY = 100;  // mm
  int64_t facets = 20000;           // about this many triangles (two per grid cell)
  double height = 0;                // h, mm; <= 0: 0.2 min(X, Y)
  double troughRadius = 0;          // r, mm; <= 0: X / 8 (trough only)

  double heightOrDefault() const;
  double troughRadiusOrDefault() const;
};

// The exact analytic height (the mesh interpolates it at the grid nodes).
double surfaceHeight(const SurfaceSpec& spec, double x, double y);

// Grid of nx x ny cells with nx / ny close to X / Y and 2 nx ny close to `facets`;
// each cell is split along its (0,0)-(1,1) diagonal; normals point up.
TriangleMesh makeAnalyticSurface(const SurfaceSpec& spec);

}  // namespace scallop
