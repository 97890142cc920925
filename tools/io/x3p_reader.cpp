// X3P reader (x3p_reader.h): the archive with libzip, main.xml with pugixml.
#include "tools/io/x3p_reader.h"

#include <fmt/format.h>
#include <zip.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <pugixml.hpp>
#include <string_view>

#include "base/input_error.h"
#include "tools/io/md5.h"
#include "tools/io/zip_error.h"

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

// main.xml parsed by pugixml. ISO 5436-2 puts the namespace prefix on the root
// (p:ISO5436_2) and writers differ on the rest, so elements are found by their local
// name, along their path from the root.
class MainXml {
 public:
  MainXml(const std::string& text, const std::string& path) : path_(path) {
    const pugi::xml_parse_result parsed = document_.load_buffer(text.data(), text.size());
    if (!parsed)
      throw InputError(path, fmt::format("main.xml is not well-formed XML: {} at byte {}",
                                         parsed.description(), parsed.offset));
    root_ = document_.document_element();
  }

  // The element at `names` below the root, or a null node.
  pugi::xml_node find(std::initializer_list<const char*> names) const {
    pugi::xml_node node = root_;
    for (const char* name : names) node = child(node, name);
    return node;
  }
  // Its text, white space trimmed; throws naming the element when it is missing.
  std::string text(std::initializer_list<const char*> names) const {
    const pugi::xml_node node = find(names);
    if (!node)
      throw InputError(path_, std::string("main.xml has no ") + *(names.end() - 1) + " element");
    return trimmed(node.text().get());
  }
  // The same, as a number.
  double number(std::initializer_list<const char*> names, const std::string& what) const {
    const std::string t = text(names);
    size_t used = 0;
    double v = NAN;
    try {
      v = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != t.size() || !std::isfinite(v))
      throw InputError(path_, "main.xml: " + what + " is \"" + t + "\", expected a number");
    return v;
  }

 private:
  static std::string_view localName(const pugi::xml_node& node) {
    const std::string_view name = node.name();
    const size_t colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
  }
  static pugi::xml_node child(const pugi::xml_node& parent, const char* name) {
    for (const pugi::xml_node& c : parent.children())
      if (c.type() == pugi::node_element && localName(c) == name) return c;
    return {};
  }
  static std::string trimmed(const std::string& text) {
    const size_t a = text.find_first_not_of(" \t\r\n"), b = text.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : text.substr(a, b - a + 1);
  }

  std::string path_;
  pugi::xml_document document_;
  pugi::xml_node root_;
};

struct Axis {
  std::string type, dataType;
  double increment = 1, offset = 0;
};

// Axis `name` (CX, CY, CZ) of Record1/Axes; DataType, Increment and Offset are optional.
Axis axis(const MainXml& xml, const char* name) {
  Axis a;
  a.type = xml.text({"Record1", "Axes", name, "AxisType"});
  if (xml.find({"Record1", "Axes", name, "DataType"}))
    a.dataType = xml.text({"Record1", "Axes", name, "DataType"});
  if (xml.find({"Record1", "Axes", name, "Increment"}))
    a.increment =
        xml.number({"Record1", "Axes", name, "Increment"}, std::string(name) + " Increment");
  if (xml.find({"Record1", "Axes", name, "Offset"}))
    a.offset = xml.number({"Record1", "Axes", name, "Offset"}, std::string(name) + " Offset");
  return a;
}

}  // namespace

ZMap readHeightsX3p(const std::string& path) {
  int error = 0;
  std::unique_ptr<zip_t, ZipCloser> zip(zip_open(path.c_str(), ZIP_RDONLY, &error));
  if (!zip) throw InputError(path, "cannot open the X3P (zip) archive: " + zipErrorText(error));
  const MainXml xml(member(zip.get(), "main.xml", path), path);
  if (xml.text({"Record1", "FeatureType"}) != "SUR")
    throw InputError(path, "main.xml: FeatureType is not SUR; expected a surface (height map)");
  const Axis cx = axis(xml, "CX"), cy = axis(xml, "CY"), cz = axis(xml, "CZ");
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
  const double sx = xml.number({"Record3", "MatrixDimension", "SizeX"}, "SizeX");
  const double sy = xml.number({"Record3", "MatrixDimension", "SizeY"}, "SizeY");
  if (!(sx >= 1 && sy >= 1 && sx == std::floor(sx) && sy == std::floor(sy) && sx * sy <= 1e12))
    throw InputError(path, "main.xml: SizeX and SizeY must be whole numbers >= 1");
  const std::string link = xml.text({"Record3", "DataLink", "PointDataLink"});
  const std::string data = member(zip.get(), link.c_str(), path);
  const uint64_t cells = uint64_t(sx) * uint64_t(sy);
  if (data.size() != cells * uint64_t(bytesPerValue))
    throw InputError(path, fmt::format("{} is {} bytes; {} x {} values of {} bytes need {}", link,
                                       data.size(), sx, sy, bytesPerValue, cells * bytesPerValue));
  if (xml.find({"Record3", "DataLink", "MD5ChecksumPointData"}) &&
      xml.text({"Record3", "DataLink", "MD5ChecksumPointData"}) != md5Hex(data))
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
