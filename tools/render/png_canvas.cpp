#include "tools/render/png_canvas.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

#include "base/input_error.h"
#include "tools/io/atomic_file.h"

namespace scallop::png {

namespace {

// DejaVu Sans from Debian's fonts-dejavu-core (scripts/install-deps.sh).
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The face, loaded once. FreeType faces are not thread-safe, so every use holds the lock.
struct Font {
  std::mutex lock;
  FT_Library library = nullptr;
  FT_Face face = nullptr;

  Font() {
    if (FT_Init_FreeType(&library) != 0) return;
    if (FT_New_Face(library, kFontFile, 0, &face) != 0) {
      face = nullptr;
      // A picture without labels is still worth writing; say once why they are missing.
      std::fprintf(stderr,
                   "scallop: warning: cannot load the font %s (fonts-dejavu-core); "
                   "pictures are drawn without text\n",
                   kFontFile);
    }
  }
  ~Font() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

Font& font() {
  static Font f;
  return f;
}

// Unicode code points of UTF-8 text; a malformed byte stands for itself.
std::vector<char32_t> codePoints(const std::string& s) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < s.size();) {
    const unsigned char b = static_cast<unsigned char>(s[i]);
    const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
    char32_t cp = extra == 0 ? b : char32_t(b & (0x3F >> extra));
    bool ok = i + size_t(extra) < s.size() + (extra == 0 ? 1 : 0);
    for (int k = 1; ok && k <= extra; ++k) {
      const unsigned char c = static_cast<unsigned char>(s[i + size_t(k)]);
      ok = (c & 0xC0) == 0x80;
      cp = (cp << 6) | (c & 0x3F);
    }
    out.push_back(ok ? cp : char32_t(b));
    i += ok ? size_t(extra) + 1 : 1;
  }
  return out;
}

int pixelSize(int scale) {
  return kTextPx * scale;
}

}  // namespace

// Text goes through FreeType itself: OpenImageIO's render_text would do the same, but
// the OpenImageIO of Debian 12 (2.4) decodes UTF-8 wrongly and draws "µ" as "5".
void Canvas::text(int x, int y, const std::string& s, int scale, Rgb c) {
  Font& f = font();
  std::lock_guard<std::mutex> hold(f.lock);
  if (!f.face || FT_Set_Pixel_Sizes(f.face, 0, FT_UInt(pixelSize(scale))) != 0) return;
  // (x, y) is the top of the capitals: the baseline is one cap height lower.
  const int baseline = y + kCapHeightPx * scale;
  int penX = x;
  for (char32_t cp : codePoints(s)) {
    if (FT_Load_Char(f.face, FT_ULong(cp), FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = f.face->glyph;
    const FT_Bitmap& bm = g->bitmap;
    for (unsigned row = 0; row < bm.rows; ++row)
      for (unsigned col = 0; col < bm.width; ++col) {
        const int cover = bm.buffer[size_t(row) * size_t(std::abs(bm.pitch)) + col];
        if (cover == 0) continue;
        const int px = penX + g->bitmap_left + int(col), py = baseline - g->bitmap_top + int(row);
        if (px < 0 || py < 0 || px >= w_ || py >= h_) continue;
        uint8_t* p = &px_[(size_t(py) * size_t(w_) + size_t(px)) * 3];
        const Rgb ink = c;
        auto mix = [cover](uint8_t under, uint8_t over) {
          return uint8_t((under * (255 - cover) + over * cover + 127) / 255);
        };
        p[0] = mix(p[0], ink.r), p[1] = mix(p[1], ink.g), p[2] = mix(p[2], ink.b);
      }
    penX += int(g->advance.x >> 6);
  }
}

int textWidth(const std::string& s, int scale) {
  Font& f = font();
  std::lock_guard<std::mutex> hold(f.lock);
  if (s.empty() || !f.face || FT_Set_Pixel_Sizes(f.face, 0, FT_UInt(pixelSize(scale))) != 0)
    return 0;
  int width = 0;
  for (char32_t cp : codePoints(s))
    if (FT_Load_Char(f.face, FT_ULong(cp), FT_LOAD_DEFAULT) == 0)
      width += int(f.face->glyph->advance.x >> 6);
  return width;
}

double niceBelow(double x) {
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * mag <= x * (1 + 1e-12)) return m * mag;
  return mag;
}

std::string formatValue(double v, int decimals, const std::string& unit) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0"
  return s + " " + unit;
}

ScaleBar scaleBarFor(double mmPerPx, int mapPx) {
  const double mm = niceBelow(0.4 * mapPx * mmPerPx);
  ScaleBar bar;
  bar.px = std::max(1, int(std::lround(mm / mmPerPx)));
  bar.label = mm >= 1 ? fmt::format("{:g} mm", mm) : fmt::format("{:g} \u00b5m", mm * 1000);
  return bar;
}

int scaleBarWidth(const ScaleBar& bar, int scale) {
  return bar.px + 10 + textWidth(bar.label, scale);
}

int drawScaleBar(Canvas& canvas, int x, int y, const ScaleBar& bar, int scale) {
  const int textH = kCapHeightPx * scale;
  canvas.fill(x, y + textH / 2 - 2, bar.px, 4, kInk);
  canvas.fill(x, y, 2, textH, kInk);
  canvas.fill(x + bar.px - 2, y, 2, textH, kInk);
  canvas.text(x + bar.px + 10, y, bar.label, scale, kInk);
  return scaleBarWidth(bar, scale);
}

void writePng(const Canvas& canvas, const std::string& path, const std::string& title) {
  OIIO::ImageSpec spec(canvas.width(), canvas.height(), 3, OIIO::TypeDesc::UINT8);
  if (!title.empty()) spec.attribute("ImageDescription", title);
  writeFileAtomically(path, [&](const std::string& temp) {
    // The format is named explicitly: the temporary name has no ".png" extension.
    auto out = OIIO::ImageOutput::create("png");
    if (!out) throw InputError(path, "PNG writer unavailable: " + OIIO::geterror());
    if (!out->open(temp, spec) || !out->write_image(OIIO::TypeDesc::UINT8, canvas.data()) ||
        !out->close())
      throw InputError(path, "cannot write PNG: " + out->geterror());
  });
}

}  // namespace scallop::png
