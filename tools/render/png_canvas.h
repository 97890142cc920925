// Small raster pictures for people: an RGB canvas with a built-in 5x7 bitmap font,
// shared by preview.png (tools/preview_png.cpp) and the design-deviation picture
// (tools/render/deviation_png.h). Text uses this font rather than OpenImageIO's render_text,
// which needs FreeType and a font file that CI machines may not have.
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

// Stands for the micro sign in label strings (the font is single-byte).
constexpr char kMicro = '\x01';

constexpr int kGlyphW = 5, kGlyphH = 7, kAdvance = 6;  // font pixels

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
  // `scale` screen pixels per font pixel; (x, y) is the top-left of the text.
  void text(int x, int y, const std::string& s, int scale, Rgb c);

 private:
  int w_, h_;
  std::vector<uint8_t> px_;
};

inline int textWidth(const std::string& s, int scale) {
  return s.empty() ? 0 : (int(s.size()) * kAdvance - 1) * scale;
}

// Largest 1, 2 or 5 times a power of ten that is <= x (x > 0).
double niceBelow(double x);

// v with `decimals` decimals and a unit ("-0" printed as "0").
std::string formatValue(double v, int decimals, const std::string& unit);

// Writes the canvas as an 8-bit RGB PNG, atomically (tools/io/atomic_file.h); `title`
// goes into the ImageDescription. Throws InputError(path, ...).
void writePng(const Canvas& canvas, const std::string& path, const std::string& title);

}  // namespace scallop::png
