// A vertical colour bar of heights for the 3-D picture (tools/render/render_png.h):
// the colour map from zLow (bottom) to zHigh (top), framed, with ticks labelled in µm
// (a range under 0.5 mm) or mm: the two ends and round values between them that leave
// room for their text.
#pragma once

#include <string>
#include <vector>

#include "tools/render/colour_map.h"
#include "tools/render/png_canvas.h"

namespace scallop {

struct ColourBarTick {
  double valueMm;
  std::string label;
};

// Ticks for a bar `barPx` tall, the two ends and round values between them at least
// `gapPx` from every other tick (the 3-D picture's bar: two text heights; preview.png's:
// a text height and 4 px).
std::vector<ColourBarTick> colourBarTicks(double zLow, double zHigh, int barPx, int gapPx);

// The width the bar with its labels takes at font `scale`, px.
int colourBarWidth(double zLow, double zHigh, int barPx, int scale);

// Draws the bar (x, y: its top left corner; its labels to its right).
void drawColourBar(png::Canvas& canvas, int x, int y, int barPx, double zLow, double zHigh,
                   ColourMap map, int scale);

}  // namespace scallop
