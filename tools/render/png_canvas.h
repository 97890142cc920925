// Small raster pictures for people: an RGB canvas with anti-aliased text (DejaVu Sans,
// UTF-8, so labels show µ and °), shared by preview.png (tools/render/preview_png.h)
// and the design-deviation picture (tools/render/deviation_png.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace scallop::png {

struct Rgb {
  uint8_t r, g, b;
};

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kInk{25, 25, 25};
constexpr Rgb kFrame{90, 90, 90};

// Text at scale 1: the font's pixel size, and the height of its capitals (what a
// layout reserves for a line of labels; descenders reach a few pixels below it).
constexpr int kTextPx = 10, kCapHeightPx = 7;

// RGB pixels, row 0 at the top; drawing outside the canvas is clipped.
class Canvas {
 public:
  Canvas(int width, int height)
      : w_(width), h_(height), px_(size_t(width) * size_t(height) * 3, 255) {}
  int width() const { return w_; }
  int height() const { return h_; }
  const uint8_t* data() const { return px_.data(); }

  void set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    uint8_t* p = &px_[(size_t(y) * size_t(w_) + size_t(x)) * 3];
    p[0] = c.r, p[1] = c.g, p[2] = c.b;
  }
  void fill(int x, int y, int w, int h, Rgb c) {
    for (int yy = y; yy < y + h; ++yy)
      for (int xx = x; xx < x + w; ++xx) set(xx, yy, c);
  }
  void frame(int x, int y, int w, int h, Rgb c) {
    fill(x - 1, y - 1, w + 2, 1, c), fill(x - 1, y + h, w + 2, 1, c);
    fill(x - 1, y, 1, h, c), fill(x + w, y, 1, h, c);
  }
  // UTF-8 text of kTextPx * scale pixels; (x, y) is the left end of the top of its
  // capitals. Drawn without text when the font is missing (a warning says so once).
  void text(int x, int y, const std::string& s, int scale, Rgb c);

 private:
  int w_, h_;
  std::vector<uint8_t> px_;
};

// The advance of `s` drawn by Canvas::text at `scale`, px.
int textWidth(const std::string& s, int scale);

// Largest 1, 2 or 5 times a power of ten that is <= x (x > 0).
double niceBelow(double x);

// v with `decimals` decimals and a unit ("-0" printed as "0").
std::string formatValue(double v, int decimals, const std::string& unit);

// The scale bar of a map drawn at `mmPerPx`: a round length (1, 2 or 5 x 10^k mm)
// about 40% of the map's width `mapPx`, and its label in mm or µm.
struct ScaleBar {
  int px = 1;
  std::string label;
};
ScaleBar scaleBarFor(double mmPerPx, int mapPx);
// Draws the bar with end ticks, its label to the right, the top of the label's capitals
// at y; returns the width drawn, px.
int drawScaleBar(Canvas& canvas, int x, int y, const ScaleBar& bar, int scale);
// The width drawScaleBar needs, px.
int scaleBarWidth(const ScaleBar& bar, int scale);

// Writes the canvas as an 8-bit RGB PNG, atomically (tools/io/atomic_file.h); `title`
// goes into the ImageDescription. Throws InputError(path, ...).
void writePng(const Canvas& canvas, const std::string& path, const std::string& title);

}  // namespace scallop::png
