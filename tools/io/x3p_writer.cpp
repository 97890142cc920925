// X3P writer (x3p_writer.h), with libzip.
#include "tools/io/x3p_writer.h"

#include <fmt/format.h>
#include <zip.h>

#include <cstdint>
#include <cstring>
#include <ctime>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/version.h"
#include "tools/io/atomic_file.h"
#include "tools/io/md5.h"
#include "tools/io/xml_text.h"
#include "tools/io/zip_error.h"

namespace scallop {

namespace {

std::string axis(const char* name, const char* type, double increment, double offset) {
  return fmt::format(
      "      <{0}>\n        <AxisType>{1}</AxisType>\n        <DataType>D</DataType>\n"
      "        <Increment>{2}</Increment>\n        <Offset>{3}</Offset>\n      </{0}>\n",
      name, type, increment, offset);
}

std::string isoDateNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// Heights in metres as little-endian float64, ZMap order.
std::string dataBin(const ZMap& map) {
  std::string bytes(map.heights().size() * 8, '\0');
  for (size_t k = 0; k < map.heights().size(); ++k) {
    const double v = map.heights()[k] * kMetrePerMm;
    uint64_t bits = 0;
    std::memcpy(&bits, &v, 8);
    for (int b = 0; b < 8; ++b) bytes[8 * k + size_t(b)] = char((bits >> (8 * b)) & 0xff);
  }
  return bytes;
}

class Archive {
 public:
  Archive(const std::string& temp, const std::string& path) : path_(path) {
    int error = 0;
    zip_ = zip_open(temp.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!zip_) throw InputError(path, "cannot create the zip archive: " + zipErrorText(error));
  }
  ~Archive() {
    if (zip_) zip_discard(zip_);
  }
  // `bytes` must live until close().
  void add(const char* name, const std::string& bytes) {
    zip_source_t* source = zip_source_buffer(zip_, bytes.data(), bytes.size(), 0);
    if (!source || zip_file_add(zip_, name, source, ZIP_FL_ENC_UTF_8) < 0) {
      if (source) zip_source_free(source);
      fail();
    }
  }
  void addDirectory(const char* name) {
    if (zip_dir_add(zip_, name, ZIP_FL_ENC_UTF_8) < 0) fail();
  }
  void close() {
    if (zip_close(zip_) != 0) fail();
    zip_ = nullptr;
  }

 private:
  [[noreturn]] void fail() {
    throw InputError(path_, std::string("cannot write the zip archive: ") + zip_strerror(zip_));
  }
  std::string path_;
  zip_t* zip_ = nullptr;
};

}  // namespace

std::string x3pMainXml(const ZMap& map, const std::string& dataMd5, const std::string& comment) {
  const GridSpec& g = map.grid();
  const double step = g.spacing * kMetrePerMm;
  std::string x = R"(<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2" )"
                  R"(xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" )"
                  R"(xsi:schemaLocation="http://www.opengps.eu/2008/ISO5436_2 )"
                  R"(http://www.opengps.eu/2008/ISO5436_2/ISO5436_2_XML.xsd">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
)";
  x += axis("CX", "I", step, g.cellCentreX(0) * kMetrePerMm);
  x += axis("CY", "I", step, g.cellCentreY(0) * kMetrePerMm);
  x += axis("CZ", "A", 1.0, 0.0);
  const std::string date = isoDateNow();
  x += fmt::format(R"(    </Axes>
  </Record1>
  <Record2>
    <Date>{0}</Date>
    <Creator>scallop {5}</Creator>
    <Instrument>
      <Manufacturer>scallop</Manufacturer>
      <Model>exact swept-solid simulation</Model>
      <Serial>none</Serial>
      <Version>{5}</Version>
    </Instrument>
    <CalibrationDate>{0}</CalibrationDate>
    <ProbingSystem>
      <Type>NonContacting</Type>
      <Identification>simulated z-map, heights exact to 1e-9 m in double</Identification>
    </ProbingSystem>
    <Comment>{1}</Comment>
  </Record2>
  <Record3>
    <MatrixDimension>
      <SizeX>{2}</SizeX>
      <SizeY>{3}</SizeY>
      <SizeZ>1</SizeZ>
    </MatrixDimension>
    <DataLink>
      <PointDataLink>bindata/data.bin</PointDataLink>
      <MD5ChecksumPointData>{4}</MD5ChecksumPointData>
    </DataLink>
  </Record3>
  <Record4>
    <ChecksumFile>md5checksum.hex</ChecksumFile>
  </Record4>
</p:ISO5436_2>
)",
                   date, xmlEscape(comment), g.nx, g.ny, dataMd5, kScallopVersion);
  return x;
}

void writeHeightsX3p(const ZMap& map, const std::string& path, const std::string& comment) {
  if (map.nx() <= 0 || map.ny() <= 0) throw InputError(path, "cannot write an empty height map");
  const std::string data = dataBin(map);
  const std::string xml = x3pMainXml(map, md5Hex(data), comment);
  const std::string checksum = md5Hex(xml) + " *main.xml\n";
  writeFileAtomically(path, [&](const std::string& temp) {
    Archive zip(temp, path);
    zip.add("main.xml", xml);
    zip.addDirectory("bindata");
    zip.add("bindata/data.bin", data);
    zip.add("md5checksum.hex", checksum);
    zip.close();
  });
}

}  // namespace scallop
