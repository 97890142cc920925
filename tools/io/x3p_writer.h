// ISO 25178-72 / ISO 5436-2 X3P export of a height map: a zip archive holding
//   main.xml          the description (Record1..Record4, below)
//   bindata/data.bin  the heights, little-endian float64 in metres, x fastest then y
//                     (ZMap order: the first row is the *smallest* y, as X3P's CY axis
//                     counts up from its offset)
//   md5checksum.hex   "<md5 of main.xml> *main.xml" (Record4's checksum file)
// main.xml: Record1 Revision "ISO5436 - 2000", FeatureType SUR, axes CX and CY
// incremental (AxisType I, DataType D, Increment = spacing in m, Offset = first cell
// centre in m), CZ absolute (AxisType A, DataType D, Increment 1, Offset 0); Record2
// creator, date and instrument ("scallop" simulation); Record3 MatrixDimension
// SizeX = nx, SizeY = ny, SizeZ = 1 and DataLink PointDataLink bindata/data.bin with
// MD5ChecksumPointData; Record4 ChecksumFile md5checksum.hex.
// Read by Gwyddion (OpenGPS module), MountainsMap and the openGPS library.
#pragma once

#include <string>

#include "raycast/zmap.h"

namespace scallop {

// The main.xml text for `map` whose data.bin has MD5 `dataMd5` (32 hex digits).
std::string x3pMainXml(const ZMap& map, const std::string& dataMd5, const std::string& comment);

// Writes the archive atomically; throws InputError(path, ...) on failure.
void writeHeightsX3p(const ZMap& map, const std::string& path, const std::string& comment);

}  // namespace scallop
