// The signed-deviation colours shared by deviation.png (the map, deviation_png.h) and
// deviation_view.png (the design seen in 3-D, deviation_view_png.h): one colour map,
// one way to choose its range, one colour bar, so the two pictures read alike.
#pragma once

#include <vector>

#include "tools/render/png_canvas.h"

namespace scallop::png {

// ColorBrewer RdBu (colour-blind safe): red at t = -1 (below the design), white at 0,
// blue at t = +1 (material left); linear between the five stops; t clamped to [-1, 1].
Rgb diverging(double t);

// The colour range's half width L, mm: the 99th percentile of |deviation| (NaN left
// out) rounded up to 1, 2 or 5 x 10^k, so that a few extreme values do not wash the
// picture out; 1e-3 mm when there is none.
double divergingLimit(const std::vector<double>& deviation);

// A vertical bar of `height` px from +limit (top) to -limit, with five ticks labelled in
// um (mm when limit >= 0.5 mm) at `scale`; the top-left corner at (x, y). Returns the
// width drawn (bar and labels), px. barLabelsWidth gives it before drawing.
int drawDivergingBar(Canvas& canvas, int x, int y, int height, double limit, int scale);
int divergingBarWidth(double limit, int scale);

// "um" or "mm" and the factor from mm, as the bar labels them.
struct DeviationUnit {
  double perMm;
  const char* name;
};
DeviationUnit deviationUnit(double limit);

}  // namespace scallop::png
