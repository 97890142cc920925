// The box of a 3-D picture (tools/render/render_png.h): the rectangle of the map's
// region on the base under the surface, drawn where the surface and its walls do not
// hide it, with ticks and labels in mm along its two edges nearest the viewer and the
// axes' names ("x (mm)", "y (mm)") beyond them.
#pragma once

#include "tools/render/png_canvas.h"
#include "tools/render/render_camera.h"
#include "tools/render/surface_render.h"

namespace scallop {

struct BoxFrame {
  double x0, y0, x1, y1;  // the rectangle, mm (ticks stay inside it)
  double z;               // world z of the base
};

// Draws onto `canvas`, whose pixel (offsetX + c, offsetY + r) is the traced image's
// (c, r); `scale` is the font scale.
void drawRenderBox(png::Canvas& canvas, int offsetX, int offsetY, const Camera& camera,
                   const TracedImage& traced, const BoxFrame& box, int scale);

}  // namespace scallop
