// X3P reader (x3p_reader.h), with libzip.
#include "tools/io/x3p_reader.h"

#include <fmt/format.h>
#include <zip.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include "base/input_error.h"
#include "tools/io/md5.h"

namespace scallop {

namespace {

constexpr double kMmPerMetre = 1e3;
constexpr uint64_t kMaxMemberBytes = uint64_t(1) << 36;  // 64 GiB: refuse before allocating

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};

// The bytes of archive member `name`.
std::string member(zip_t* zip, const char* name, const std::string& path) {
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat(zip, name, 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    throw InputError(path, std::string("no ") + name + " in the X3P archive");
  if (st.size > kMaxMemberBytes)
    throw InputError(path, fmt::format("{} is {} bytes, more than scallop reads", name, st.size));
  std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> file(zip_fopen(zip, name, 0), zip_fclose);
  if (!file) throw InputError(path, std::string("cannot open ") + name + " in the archive");
  std::string bytes(size_t(st.size), '\0');
  if (zip_fread(file.get(), bytes.data(), st.size) != zip_int64_t(st.size))
    throw InputError(path, std::string("cannot read ") + name + " (a damaged archive)");
  return bytes;
}

// The text of the first <tag>...</tag> in `xml` (a namespace prefix on the tag is
// allowed), or throws naming it.
std::string element(const std::string& xml, const std::string& tag, const std::string& path) {
  for (size_t at = xml.find(tag); at != std::string::npos; at = xml.find(tag, at + 1)) {
    const size_t open = xml.rfind('<', at);
    const size_t close = at + tag.size();
    if (open == std::string::npos || close >= xml.size() || xml[close] != '>') continue;
    const std::string prefix = xml.substr(open + 1, at - open - 1);
    if (prefix.find_first_of("</> \t\n") != std::string::npos) continue;  // another tag
    const size_t stop = xml.find("</" + prefix + tag + ">", close);
    if (stop == std::string::npos) break;
    const std::string text = xml.substr(close + 1, stop - close - 1);
    const size_t a = text.find_first_not_of(" \t\r\n"), b = text.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : text.substr(a, b - a + 1);
  }
  throw InputError(path, "main.xml has no " + tag + " element");
}

double number(const std::string& text, const std::string& what, const std::string& path) {
  size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw InputError(path, "main.xml: " + what + " is \"" + text + "\", expected a number");
  return v;
}

struct Axis {
  std::string type, dataType;
  double increment = 1, offset = 0;
};

Axis axis(const std::string& xml, const std::string& name, const std::string& path) {
  const std::string block = element(xml, name, path);
  Axis a;
  a.type = element(block, "AxisType", path);
  if (block.find("DataType>") != std::string::npos) a.dataType = element(block, "DataType", path);
  if (block.find("Increment>") != std::string::npos)
    a.increment = number(element(block, "Increment", path), name + " Increment", path);
  if (block.find("Offset>") != std::string::npos)
    a.offset = number(element(block, "Offset", path), name + " Offset", path);
  return a;
}

}  // namespace

ZMap readHeightsX3p(const std::string& path) {
  int error = 0;
  std::unique_ptr<zip_t, ZipCloser> zip(zip_open(path.c_str(), ZIP_RDONLY, &error));
  if (!zip) {
    zip_error_t e;
    zip_error_init_with_code(&e, error);
    const std::string why = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw InputError(path, "cannot open the X3P (zip) archive: " + why);
  }
  const std::string xml = member(zip.get(), "main.xml", path);
  if (element(xml, "FeatureType", path) != "SUR")
    throw InputError(path, "main.xml: FeatureType is not SUR; expected a surface (height map)");
  const Axis cx = axis(xml, "CX", path), cy = axis(xml, "CY", path), cz = axis(xml, "CZ", path);
  if (cx.type != "I" || cy.type != "I")
    throw InputError(path, "main.xml: CX and CY must be incremental axes (AxisType I)");
  if (!(cx.increment > 0) || std::fabs(cx.increment - cy.increment) > 1e-9 * cx.increment)
    throw InputError(path, fmt::format("main.xml: CX and CY increments are {} and {} m; "
                                       "expected the same length > 0 (square cells)",
                                       cx.increment, cy.increment));
  if (cz.type != "A") throw InputError(path, "main.xml: CZ must be an absolute axis (AxisType A)");
  const int bytesPerValue = cz.dataType == "F" ? 4 : cz.dataType == "D" ? 8 : 0;
  if (!bytesPerValue)
    throw InputError(path, "main.xml: CZ DataType is \"" + cz.dataType +
                               "\"; expected D (float64) or F (float32)");
  const double sx = number(element(xml, "SizeX", path), "SizeX", path);
  const double sy = number(element(xml, "SizeY", path), "SizeY", path);
  if (!(sx >= 1 && sy >= 1 && sx == std::floor(sx) && sy == std::floor(sy) && sx * sy <= 1e12))
    throw InputError(path, "main.xml: SizeX and SizeY must be whole numbers >= 1");
  const std::string link = element(xml, "PointDataLink", path);
  const std::string data = member(zip.get(), link.c_str(), path);
  const uint64_t cells = uint64_t(sx) * uint64_t(sy);
  if (data.size() != cells * uint64_t(bytesPerValue))
    throw InputError(path, fmt::format("{} is {} bytes; {} x {} values of {} bytes need {}", link,
                                       data.size(), sx, sy, bytesPerValue, cells * bytesPerValue));
  if (xml.find("MD5ChecksumPointData>") != std::string::npos &&
      element(xml, "MD5ChecksumPointData", path) != md5Hex(data))
    throw InputError(path, link + " does not match main.xml's MD5ChecksumPointData");

  GridSpec g;
  g.spacing = cx.increment * kMmPerMetre;
  g.originX = cx.offset * kMmPerMetre - 0.5 * g.spacing;
  g.originY = cy.offset * kMmPerMetre - 0.5 * g.spacing;
  g.nx = int64_t(sx);
  g.ny = int64_t(sy);
  ZMap map(g, 0.0);
  std::vector<double>& h = map.heights();
  for (size_t k = 0; k < h.size(); ++k) {
    uint64_t bits = 0;
    for (int b = 0; b < bytesPerValue; ++b)
      bits |= uint64_t(static_cast<unsigned char>(data[k * bytesPerValue + size_t(b)])) << (8 * b);
    double v = 0;
    if (bytesPerValue == 8) {
      std::memcpy(&v, &bits, 8);
    } else {
      const uint32_t bits32 = uint32_t(bits);
      float f = 0;
      std::memcpy(&f, &bits32, 4);
      v = f;
    }
    h[k] = (v * cz.increment + cz.offset) * kMmPerMetre;
  }
  return map;
}

}  // namespace scallop
