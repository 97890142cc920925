// deviation_view.png: the design surface seen in 3-D, coloured by its normal deviation
// (analysis/normal_deviation.h), for people: where the scallops stand and where the
// cutter went below the design, on the part's own shape, walls and undercuts included.
//
// A view from `azimuth` (degrees about +z from +x) and `elevation` (degrees above the
// xy plane; 90 looks straight down), orthographic or in perspective, with the camera of
// the 3-D height pictures (tools/render/render_camera.h). Each pixel is the mean of a
// fixed 2 x 2 grid of rays traced with Embree (tools/render/mesh_scene.h): the first
// facet a ray meets gives the colour, its deviation interpolated linearly from its three
// vertices (as the areas of the report take it), on the diverging map of deviation.png
// (red below the design, white 0, blue material left; range +-L, L the 99th percentile
// of |deviation| rounded up), shaded by 0.3 + 0.7 lit max(0, n . l), n the facet's
// normal turned to the viewer (a design need not be closed) and lit 0 where the shadow
// ray towards the light meets another facet. The light is above the viewer's right
// shoulder unless given. Facets with a vertex without a value (NaN: no material,
// unresolved) are grey. A colour bar and the view's angles beside it. Deterministic: the
// same bits whatever the thread count.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "tools/render/png_canvas.h"
#include "tools/render/render_camera.h"

namespace scallop {

struct DeviationView {
  double azimuthDeg = 30;    // about +z, from +x
  double elevationDeg = 35;  // above the xy plane, in [-90, 90]
  Projection projection = Projection::kOrthographic;
  // Where the light comes from, as the height pictures' (azimuth clockwise from +y,
  // elevation above the horizon); NaN: above the viewer's right shoulder.
  Direction light{NAN, NAN};
};

// The picture before it is written, and where a point of the design lands on it.
struct DeviationViewImage {
  png::Canvas canvas{1, 1};
  double limitMm = 0;  // L, the colour range's half width
  Camera camera;       // of the map part, whose top left pixel is (mapX, mapY)
  int mapX = 0, mapY = 0;
  // The pixel (column, row) of a world point (mm).
  std::pair<int, int> pixelOf(const Vec3& p) const;
};

DeviationViewImage renderDeviationView(const TriangleMesh& design,
                                       const std::vector<double>& deviation,
                                       const DeviationView& view, const std::string& title,
                                       int widthPx = 800);

// Renders and writes atomically (tools/io/atomic_file.h); returns L, mm.
double writeDeviationViewPng(const TriangleMesh& design, const std::vector<double>& deviation,
                             const DeviationView& view, const std::string& path,
                             const std::string& title);

}  // namespace scallop
