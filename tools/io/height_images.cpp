// OpenEXR and Gwyddion Simple Field writers and readers (formats: height_images.h).
#include "tools/io/height_images.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/internal_error.h"
#include "tools/io/atomic_file.h"

namespace scallop {

namespace {

constexpr const char* kOriginX = "scallop:origin_x";
constexpr const char* kOriginY = "scallop:origin_y";
constexpr const char* kSpacing = "scallop:spacing_mm";
constexpr const char* kGsfMagic = "Gwyddion Simple Field 1.0\n";

// Rows per write call: bounds the float buffer for very large maps (a 20000 x 20000
// map would otherwise need 1.6 GB next to the ZMap itself).
constexpr int64_t kRowsPerChunk = 256;

void checkWritable(const ZMap& map, const std::string& path) {
  if (map.nx() <= 0 || map.ny() <= 0) throw InputError(path, "cannot write an empty height map");
  if (!(map.grid().spacing > 0) || !std::isfinite(map.grid().spacing))
    throw InputError(path, fmt::format("grid spacing {} mm is not positive", map.grid().spacing));
  // OpenEXR and GSF store sizes as 32-bit ints.
  if (map.nx() > INT32_MAX || map.ny() > INT32_MAX)
    throw InputError(path, fmt::format("height map of {} x {} cells is too large for an image",
                                       map.nx(), map.ny()));
}

// Heights of image row `row` (0 = largest y) as float in `unit` per mm.
void imageRow(const ZMap& map, int64_t row, double scale, float* out) {
  const int64_t j = map.ny() - 1 - row;
  for (int64_t i = 0; i < map.nx(); ++i) out[i] = float(map.at(i, j) * scale);
}

std::string describeGrid(const GridSpec& g) {
  return fmt::format(
      "scallop height map: Z = absolute height in mm; {} x {} cells of {} mm; "
      "cell (i, j) centre = ({} + (i + 0.5) s, {} + (j + 0.5) s) mm; "
      "image row 0 is the largest y (north up)",
      g.nx, g.ny, g.spacing, g.originX, g.originY);
}

// Reads a number stored by us as double, or by someone else as float or text.
bool numberAttribute(const OIIO::ImageSpec& spec, const char* name, double& value) {
  const OIIO::TypeDesc type = spec.getattributetype(name);
  if (type == OIIO::TypeDesc::DOUBLE)
    return spec.getattribute(name, OIIO::TypeDesc::DOUBLE, &value);
  if (type == OIIO::TypeDesc::FLOAT) {
    float f = 0;
    if (!spec.getattribute(name, OIIO::TypeDesc::FLOAT, &f)) return false;
    value = f;
    return true;
  }
  if (type == OIIO::TypeDesc::STRING) {
    const std::string text(spec.get_string_attribute(name));
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0';
  }
  return false;
}

void putFloatLE(float f, unsigned char* out) {
  uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  for (int b = 0; b < 4; ++b) out[b] = static_cast<unsigned char>(bits >> (8 * b));
}

float getFloatLE(const unsigned char* in) {
  uint32_t bits = 0;
  for (int b = 0; b < 4; ++b) bits |= uint32_t(in[b]) << (8 * b);
  float f = 0;
  std::memcpy(&f, &bits, 4);
  return f;
}

// A GSF header value must stay on one line and may not contain NUL.
std::string oneLine(const std::string& text) {
  std::string s = text;
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\0') c = ' ';
  return s;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

double parseGsfNumber(const std::string& path, const std::map<std::string, std::string>& keys,
                      const std::string& key, double fallback) {
  const auto it = keys.find(key);
  if (it == keys.end()) return fallback;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (end == it->second.c_str() || *end != '\0' || !std::isfinite(v))
    throw InputError(path, fmt::format("header field {} = '{}' is not a number", key, it->second));
  return v;
}

// Metres per unit for the GSF length units we accept.
double metresPerUnit(const std::string& path, const std::string& key, const std::string& unit) {
  if (unit.empty() || unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\xC2\xB5m") return 1e-6;
  if (unit == "nm") return 1e-9;
  throw InputError(path,
                   fmt::format("header field {} = '{}': expected m, mm, um or nm", key, unit));
}

// NaN is a cell without material (a frame's line that misses the stock; Gwyddion's
// masked points), which the statistics leave out; an infinite height is refused.
InputError infiniteHeight(const std::string& path, int64_t row, int64_t column) {
  return InputError(path, fmt::format("the height at image row {}, column {} is infinite; "
                                      "a cell holds a finite height or NaN (no material)",
                                      row, column));
}

OIIO::ImageSpec exrSpec(const GridSpec& g, const std::string& frame) {
  OIIO::ImageSpec spec(int(g.nx), int(g.ny), 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Z"};
  spec.attribute("compression", "zip");
  spec.attribute("ImageDescription", describeGrid(g));
  spec.attribute(kOriginX, OIIO::TypeDesc::DOUBLE, &g.originX);
  spec.attribute(kOriginY, OIIO::TypeDesc::DOUBLE, &g.originY);
  spec.attribute(kSpacing, OIIO::TypeDesc::DOUBLE, &g.spacing);
  if (!frame.empty()) spec.attribute("scallop:frame", frame);
  return spec;
}

std::string gsfHeader(const GridSpec& g, const std::string& title, const std::string& frame) {
  // Numbers use fmt's shortest representation that reads back to the same double
  // (as exact as "%.17g", without its noise digits: 0.000875, not 0.00087500000000000002).
  std::string header = kGsfMagic;
  header += fmt::format("XRes = {}\nYRes = {}\n", g.nx, g.ny);
  header += fmt::format("XReal = {}\nYReal = {}\n", double(g.nx) * g.spacing * kMetrePerMm,
                        double(g.ny) * g.spacing * kMetrePerMm);
  header +=
      fmt::format("XOffset = {}\nYOffset = {}\n", g.originX * kMetrePerMm, g.originY * kMetrePerMm);
  header += "XYUnits = m\nZUnits = m\n";
  header += "Title = " + oneLine(title) + "\n";
  if (!frame.empty()) header += "ScallopFrame = " + oneLine(frame) + "\n";
  // 1 to 4 NULs: at least one terminates the text even when it is already aligned.
  header.append(4 - header.size() % 4, '\0');
  return header;
}

// Image row `row` of `map` (0 = its largest y) in metres, little-endian float32.
void writeGsfRow(const ZMap& map, int64_t row, std::vector<unsigned char>& bytes,
                 std::ofstream& out) {
  std::vector<float> values(size_t(map.nx()));
  imageRow(map, row, kMetrePerMm, values.data());
  for (size_t i = 0; i < values.size(); ++i) putFloatLE(values[i], &bytes[4 * i]);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace

void writeHeightsExr(const ZMap& map, const std::string& path, const std::string& frame) {
  checkWritable(map, path);
  const GridSpec& g = map.grid();
  const OIIO::ImageSpec spec = exrSpec(g, frame);

  writeFileAtomically(path, [&](const std::string& temp) {
    // The format is named explicitly: the temporary name has no ".exr" extension.
    auto out = OIIO::ImageOutput::create("openexr");
    if (!out) throw InputError(path, "OpenEXR writer unavailable: " + OIIO::geterror());
    if (!out->open(temp, spec)) throw InputError(path, "cannot write OpenEXR: " + out->geterror());
    std::vector<float> rows(size_t(std::min<int64_t>(kRowsPerChunk, g.ny) * g.nx));
    for (int64_t y0 = 0; y0 < g.ny; y0 += kRowsPerChunk) {
      const int64_t y1 = std::min<int64_t>(g.ny, y0 + kRowsPerChunk);
      for (int64_t r = y0; r < y1; ++r) imageRow(map, r, 1.0, rows.data() + (r - y0) * g.nx);
      if (!out->write_scanlines(int(y0), int(y1), 0, OIIO::TypeDesc::FLOAT, rows.data()))
        throw InputError(path, "cannot write OpenEXR: " + out->geterror());
    }
    if (!out->close()) throw InputError(path, "cannot write OpenEXR: " + out->geterror());
  });
}

ZMap readHeightsExr(const std::string& path, std::string* frame) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int channel = spec.channelindex("Z") >= 0 ? spec.channelindex("Z") : 0;
  if (spec.channelindex("Z") < 0 && spec.nchannels != 1)
    throw InputError(path, "expected a channel named Z or a single channel");
  GridSpec g;
  g.nx = spec.width;
  g.ny = spec.height;
  if (!numberAttribute(spec, kOriginX, g.originX) || !numberAttribute(spec, kOriginY, g.originY) ||
      !numberAttribute(spec, kSpacing, g.spacing))
    throw InputError(path,
                     fmt::format("missing grid attributes {}, {}, {} (not a scallop height map?)",
                                 kOriginX, kOriginY, kSpacing));
  if (!(g.spacing > 0) || !std::isfinite(g.spacing))
    throw InputError(path, fmt::format("{} must be a positive number", kSpacing));
  if (frame) *frame = spec.get_string_attribute("scallop:frame");

  std::vector<float> pixels(size_t(g.cells()));
  if (!in->read_image(0, 0, channel, channel + 1, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError(path, "cannot read image: " + in->geterror());
  ZMap map(g, 0.0);
  for (int64_t row = 0; row < g.ny; ++row)
    for (int64_t i = 0; i < g.nx; ++i) {
      const float z = pixels[size_t(row * g.nx + i)];
      if (std::isinf(z)) throw infiniteHeight(path, row, i);
      map.at(i, g.ny - 1 - row) = double(z);
    }
  return map;
}

void writeHeightsGsf(const ZMap& map, const std::string& path, const std::string& title,
                     const std::string& frame) {
  checkWritable(map, path);
  const GridSpec& g = map.grid();
  const std::string header = gsfHeader(g, title, frame);

  writeFileAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError(path, "cannot open for writing: " + std::string(std::strerror(errno)));
    out.write(header.data(), std::streamsize(header.size()));
    std::vector<unsigned char> bytes(size_t(g.nx) * 4);
    for (int64_t r = 0; r < g.ny && out; ++r) writeGsfRow(map, r, bytes, out);
    out.close();
    if (!out) throw InputError(path, "cannot write: " + std::string(std::strerror(errno)));
  });
}

ZMap readHeightsGsf(const std::string& path, std::string* frame) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open: " + std::string(std::strerror(errno)));
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  const size_t magicSize = std::strlen(kGsfMagic);
  if (bytes.size() < magicSize || std::memcmp(bytes.data(), kGsfMagic, magicSize) != 0)
    throw InputError(
        path, "not a Gwyddion Simple Field file (expected the line 'Gwyddion Simple Field 1.0')");
  const auto nul = std::find(bytes.begin() + long(magicSize), bytes.end(), 0);
  if (nul == bytes.end()) throw InputError(path, "GSF header is not terminated by NUL");
  const size_t headerEnd = size_t(nul - bytes.begin());
  const size_t dataStart = headerEnd + 4 - headerEnd % 4;

  std::map<std::string, std::string> keys;
  const std::string text(bytes.begin() + long(magicSize), nul);
  size_t lineStart = 0;
  int lineNo = 1;
  while (lineStart < text.size()) {
    size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    const std::string line = text.substr(lineStart, lineEnd - lineStart);
    ++lineNo;
    lineStart = lineEnd + 1;
    if (trim(line).empty()) continue;
    const size_t eq = line.find('=');
    if (eq == std::string::npos)
      throw InputError(fmt::format("{}:{}", path, lineNo), "expected 'Name = value' in GSF header");
    keys[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }

  if (frame) *frame = keys.count("ScallopFrame") ? keys["ScallopFrame"] : "";
  GridSpec g;
  const double xres = parseGsfNumber(path, keys, "XRes", -1);
  const double yres = parseGsfNumber(path, keys, "YRes", -1);
  if (!(xres >= 1 && yres >= 1) || xres != std::floor(xres) || yres != std::floor(yres) ||
      xres > INT32_MAX || yres > INT32_MAX)
    throw InputError(path, "header fields XRes and YRes must be positive integers");
  g.nx = int64_t(xres);
  g.ny = int64_t(yres);
  const double xyScale =
      metresPerUnit(path, "XYUnits", keys.count("XYUnits") ? keys["XYUnits"] : "") * 1e3;
  const double zScale =
      metresPerUnit(path, "ZUnits", keys.count("ZUnits") ? keys["ZUnits"] : "") * 1e3;
  // Gwyddion's defaults for missing real sizes/offsets are 1 and 0.
  const double xreal = parseGsfNumber(path, keys, "XReal", 1.0) * xyScale;
  const double yreal = parseGsfNumber(path, keys, "YReal", 1.0) * xyScale;
  g.originX = parseGsfNumber(path, keys, "XOffset", 0.0) * xyScale;
  g.originY = parseGsfNumber(path, keys, "YOffset", 0.0) * xyScale;
  if (!(xreal > 0) || !(yreal > 0))
    throw InputError(path, "header fields XReal and YReal must be positive lengths");
  g.spacing = xreal / double(g.nx);
  const double dy = yreal / double(g.ny);
  if (!(g.spacing > 0) || std::abs(dy - g.spacing) > 1e-9 * g.spacing)
    throw InputError(path, fmt::format("cells are not square (XReal/XRes = {} mm, YReal/YRes = "
                                       "{} mm); a height map needs square cells",
                                       g.spacing, dy));

  const uint64_t expected = uint64_t(dataStart) + 4ull * uint64_t(g.nx) * uint64_t(g.ny);
  if (bytes.size() != expected)
    throw InputError(path,
                     fmt::format("file is {} bytes; header and {} x {} float32 values need {}",
                                 bytes.size(), g.nx, g.ny, expected));
  ZMap map(g, 0.0);
  const unsigned char* p = bytes.data() + dataStart;
  for (int64_t row = 0; row < g.ny; ++row)
    for (int64_t i = 0; i < g.nx; ++i, p += 4) {
      const float z = getFloatLE(p);
      if (std::isinf(z)) throw infiniteHeight(path, row, i);
      map.at(i, g.ny - 1 - row) = double(z) * zScale;
    }
  return map;
}

struct HeightStreamWriter::Impl {
  GridSpec grid;
  int tileHeight = 0;
  int64_t rowsWritten = 0;  // image rows, from the top
  AtomicFile exrFile, gsfFile;
  std::unique_ptr<OIIO::ImageOutput> exr;
  std::ofstream gsf;
  std::vector<float> tiles;  // one band of float32 heights, image row order
  std::vector<unsigned char> gsfRow;

  [[noreturn]] void failExr() const {
    throw InputError(exrFile.path(), "cannot write OpenEXR: " + exr->geterror());
  }
};

HeightStreamWriter::HeightStreamWriter(const GridSpec& grid, const std::string& exrPath,
                                       const std::string& gsfPath, const std::string& title,
                                       int tileHeight, const std::string& frame)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (grid.nx <= 0 || grid.ny <= 0 || grid.nx > INT32_MAX || grid.ny > INT32_MAX)
    throw InputError(
        exrPath, fmt::format("a height map of {} x {} cells cannot be an image", grid.nx, grid.ny));
  m.grid = grid;
  m.tileHeight = std::max(1, tileHeight);
  OIIO::ImageSpec spec = exrSpec(grid, frame);
  spec.tile_width = int(std::min<int64_t>(256, grid.nx));
  spec.tile_height = m.tileHeight;
  spec.tile_depth = 1;
  // The format is named explicitly: the temporary name has no ".exr" extension.
  m.exr = OIIO::ImageOutput::create("openexr");
  if (!m.exr) throw InputError(exrPath, "OpenEXR writer unavailable: " + OIIO::geterror());
  if (!m.exr->open(m.exrFile.open(exrPath), spec)) m.failExr();
  m.gsf.open(m.gsfFile.open(gsfPath), std::ios::binary | std::ios::trunc);
  const std::string header = gsfHeader(grid, title, frame);
  m.gsf.write(header.data(), std::streamsize(header.size()));
  if (!m.gsf) throw InputError(gsfPath, "cannot write: " + std::string(std::strerror(errno)));
  m.gsfRow.resize(size_t(grid.nx) * 4);
}

HeightStreamWriter::~HeightStreamWriter() = default;

void HeightStreamWriter::append(const ZMap& band) {
  Impl& m = *impl_;
  const int64_t rows = band.ny(), r0 = m.rowsWritten, r1 = r0 + rows;
  if (band.nx() != m.grid.nx || r1 > m.grid.ny || band.grid().offsetJ != m.grid.ny - r1 ||
      (r1 < m.grid.ny && rows % m.tileHeight != 0))
    throw InternalError(m.exrFile.path() + ": band does not continue the image");
  m.tiles.resize(size_t(rows * band.nx()));
  for (int64_t r = 0; r < rows; ++r) imageRow(band, r, 1.0, m.tiles.data() + r * band.nx());
  if (!m.exr->write_tiles(0, int(band.nx()), int(r0), int(r1), 0, 1, OIIO::TypeDesc::FLOAT,
                          m.tiles.data()))
    m.failExr();
  for (int64_t r = 0; r < rows && m.gsf; ++r) writeGsfRow(band, r, m.gsfRow, m.gsf);
  if (!m.gsf)
    throw InputError(m.gsfFile.path(), "cannot write: " + std::string(std::strerror(errno)));
  m.rowsWritten = r1;
}

void HeightStreamWriter::close() {
  Impl& m = *impl_;
  if (m.rowsWritten != m.grid.ny)
    throw InternalError(m.exrFile.path() + ": closed before every row was written");
  if (!m.exr->close()) m.failExr();
  m.gsf.close();
  if (!m.gsf)
    throw InputError(m.gsfFile.path(), "cannot write: " + std::string(std::strerror(errno)));
  m.exrFile.commit();
  m.gsfFile.commit();
}

}  // namespace scallop
