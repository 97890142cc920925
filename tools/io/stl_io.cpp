#include "tools/io/stl_io.h"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/input_error.h"
#include "tools/io/atomic_file.h"

namespace scallop {

const char* toString(StlFormat format) {
  return format == StlFormat::Binary ? "binary" : "ascii";
}

namespace {

constexpr size_t kHeader = 84, kRecord = 50;

// Little-endian reads independent of the host's alignment rules.
uint32_t readU32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}
float readF32(const char* p) {
  const uint32_t u = readU32(p);
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

bool startsWithSolid(const std::string& bytes) {
  size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  return bytes.compare(i, 5, "solid") == 0;
}

std::vector<std::array<Vec3, 3>> parseBinary(const std::string& bytes, const std::string& name) {
  const uint64_t n = readU32(bytes.data() + 80);
  std::vector<std::array<Vec3, 3>> soup;
  soup.reserve(size_t(n));
  for (uint64_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + kHeader + t * kRecord;
    std::array<Vec3, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const char* v = rec + 12 + 12 * k;  // after the stored normal
      tri[size_t(k)] = {double(readF32(v)), double(readF32(v + 4)), double(readF32(v + 8))};
      if (!isFinite(tri[size_t(k)]))
        throw InputError(
            name, fmt::format("triangle {}: vertex {} has a non-finite coordinate ({}, {}, {})",
                              t + 1, k + 1, tri[size_t(k)].x, tri[size_t(k)].y, tri[size_t(k)].z));
    }
    soup.push_back(tri);
  }
  return soup;
}

// ---- ASCII ---------------------------------------------------------------------------

class Tokens {
 public:
  Tokens(const std::string& text, const std::string& name) : s_(text), name_(name) {}

  // The next whitespace-separated word, or "" at the end of the file.
  std::string next() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
    tokenLine_ = line_;
    const size_t start = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  void skipLine() {
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
  }
  void expect(const char* word, const std::string& context) {
    const std::string t = next();
    if (t != word) fail(fmt::format("expected '{}'{}, found {}", word, context, quoted(t)));
  }
  double number(const char* what) {
    const std::string t = next();
    if (t.empty()) fail(fmt::format("unexpected end of file, expected {}", what));
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size()) fail(fmt::format("expected {}, found {}", what, quoted(t)));
    if (!std::isfinite(v)) fail(fmt::format("{} '{}' is not a finite number", what, t));
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}:{}", name_, tokenLine_), what);
  }
  static std::string quoted(const std::string& t) {
    return t.empty() ? "the end of the file"
                     : "'" + (t.size() > 40 ? t.substr(0, 40) + "..." : t) + "'";
  }

 private:
  const std::string& s_;
  const std::string& name_;
  size_t pos_ = 0;
  int64_t line_ = 1, tokenLine_ = 1;
};

std::vector<std::array<Vec3, 3>> parseAscii(const std::string& bytes, const std::string& name) {
  Tokens tk(bytes, name);
  std::vector<std::array<Vec3, 3>> soup;
  tk.expect("solid", "");
  tk.skipLine();  // the solid's name
  for (;;) {
    const std::string t = tk.next();
    if (t == "endsolid") {
      tk.skipLine();
      const std::string after = tk.next();
      if (after.empty()) break;
      if (after != "solid")
        tk.fail("expected 'solid' or the end of the file after 'endsolid', found " +
                Tokens::quoted(after));
      tk.skipLine();
      continue;
    }
    if (t != "facet") tk.fail("expected 'facet' or 'endsolid', found " + Tokens::quoted(t));
    const std::string ctx = fmt::format(" in facet {}", soup.size() + 1);
    tk.expect("normal", ctx);
    // Stored normals are recomputed from the winding; they only have to be numbers.
    for (int k = 0; k < 3; ++k) {
      const std::string w = tk.next();
      if (w.empty()) tk.fail("unexpected end of file" + ctx);
    }
    tk.expect("outer", ctx);
    tk.expect("loop", ctx);
    std::array<Vec3, 3> tri;
    for (int k = 0; k < 3; ++k) {
      tk.expect("vertex", ctx);
      const std::string what = fmt::format("vertex coordinate{}", ctx);
      const double x = tk.number(what.c_str()), y = tk.number(what.c_str()),
                   z = tk.number(what.c_str());
      tri[size_t(k)] = {x, y, z};
    }
    tk.expect("endloop", ctx + " (a facet has exactly 3 vertices)");
    tk.expect("endfacet", ctx);
    soup.push_back(tri);
  }
  return soup;
}

}  // namespace

std::vector<std::array<Vec3, 3>> parseStl(const std::string& bytes, const std::string& name,
                                          StlFormat* format) {
  if (bytes.size() >= kHeader) {
    const uint64_t n = readU32(bytes.data() + 80);
    const uint64_t expected = kHeader + kRecord * n;
    if (bytes.size() == expected) {
      if (format) *format = StlFormat::Binary;
      return parseBinary(bytes, name);
    }
    const bool text = startsWithSolid(bytes) && bytes.find('\0') == std::string::npos;
    if (!text) {
      // Either a damaged binary STL or not an STL at all: say both, with the numbers.
      const std::string asBinary =
          bytes.size() < expected
              ? fmt::format("truncated in triangle {}", (bytes.size() - kHeader) / kRecord + 1)
              : fmt::format("{} bytes too long", bytes.size() - expected);
      throw InputError(
          name,
          fmt::format("not a valid STL: not ASCII STL text (which begins with 'solid'), and as "
                      "binary its header declares {} triangles ({} bytes) but the file has "
                      "{} bytes: {}",
                      n, expected, bytes.size(), asBinary));
    }
  } else if (!startsWithSolid(bytes)) {
    throw InputError(name,
                     fmt::format("not an STL file: {} bytes, shorter than a binary STL's 84-byte "
                                 "header, and it does not begin with 'solid'",
                                 bytes.size()));
  }
  if (format) *format = StlFormat::Ascii;
  return parseAscii(bytes, name);
}

TriangleMesh readStl(const std::string& path, StlInfo* info) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path, "is a folder, expected an STL file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path, "read error");
  const std::string bytes = s.str();
  StlInfo local;
  StlInfo& inf = info ? *info : local;
  const auto soup = parseStl(bytes, path, &inf.format);
  inf.facets = soup.size();
  if (soup.empty()) throw InputError(path, "the STL holds no triangles");
  TriangleMesh mesh = meshFromTriangles(soup, &inf.repairs);
  if (mesh.triangles.empty())
    throw InputError(path, fmt::format("all {} triangles are degenerate (zero area)", soup.size()));
  return mesh;
}

void writeStl(const TriangleMesh& mesh, const std::string& path, StlFormat format,
              const std::string& header) {
  writeStreamAtomically(path, "the STL file", [&](std::ostream& out) {
    if (format == StlFormat::Binary) {  // little-endian float32, as on every supported host
      std::string h = header.substr(0, 80);
      if (h.compare(0, 5, "solid") == 0) h[0] = 'S';  // a binary header must not look like ASCII
      h.resize(80, ' ');
      out.write(h.data(), 80);
      const uint32_t n = uint32_t(mesh.triangles.size());
      const unsigned char cnt[4] = {uint8_t(n), uint8_t(n >> 8), uint8_t(n >> 16),
                                    uint8_t(n >> 24)};
      out.write(reinterpret_cast<const char*>(cnt), 4);
      for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        float rec[12];
        const Vec3& nn = mesh.normals[t];
        rec[0] = float(nn.x), rec[1] = float(nn.y), rec[2] = float(nn.z);
        const auto c = mesh.corners(t);
        for (int k = 0; k < 3; ++k)
          rec[3 + 3 * k] = float(c[size_t(k)].x), rec[4 + 3 * k] = float(c[size_t(k)].y),
                      rec[5 + 3 * k] = float(c[size_t(k)].z);
        out.write(reinterpret_cast<const char*>(rec), sizeof rec);
        const char attr[2] = {0, 0};
        out.write(attr, 2);
      }
    } else {
      out << "solid " << header << "\n";
      for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3& nn = mesh.normals[t];
        out << fmt::format("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop\n", nn.x, nn.y,
                           nn.z);
        for (const Vec3& v : mesh.corners(t))
          out << fmt::format("      vertex {:.17g} {:.17g} {:.17g}\n", double(float(v.x)),
                             double(float(v.y)), double(float(v.z)));
        out << "    endloop\n  endfacet\n";
      }
      out << "endsolid " << header << "\n";
    }
  });
}

}  // namespace scallop
