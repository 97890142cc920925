// deviation_view.png: the design surface seen in 3-D, coloured by its normal deviation
// (analysis/normal_deviation.h), for people: where the scallops stand and where the
// cutter went below the design, on the part's own shape, walls and undercuts included.
//
// An orthographic view from `azimuth` (degrees about +z from +x) and `elevation`
// (degrees above the xy plane; 90 looks straight down). Each facet is drawn with a
// depth buffer at one sample a pixel, its colour the deviation interpolated linearly
// from its three vertices (as the areas of the report take it), on the diverging map of
// deviation.png (red below the design, white 0, blue material left; range +-L, L the
// 99th percentile of |deviation| rounded up), lit by a light at the viewer's shoulder
// (both sides of a facet lit alike: a design need not be closed). Facets with a vertex
// without a value (NaN: no material, unresolved) are grey. A colour bar and the view's
// angles beside it. Deterministic: the same bits whatever the thread count (one thread
// draws).
#pragma once

#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "tools/render/png_canvas.h"

namespace scallop {

struct DeviationView {
  double azimuthDeg = 30;    // about +z, from +x
  double elevationDeg = 35;  // above the xy plane, in [-90, 90]
};

// The picture before it is written, and where a point of the design lands on it.
struct DeviationViewImage {
  png::Canvas canvas{1, 1};
  double limitMm = 0;  // L, the colour range's half width
  // The pixel (column, row) of a world point (mm), as the facets are drawn.
  double originX = 0, originY = 0, pxPerMm = 1;
  Vec3 right, up;
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
