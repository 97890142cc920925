// ISO 25178-72 / ISO 5436-2 X3P import of a height map: the archive x3p_writer.h
// writes, and others of the same shape (Gwyddion's and MountainsMap's exports of a
// surface): FeatureType SUR, CX and CY incremental with the same Increment (square
// cells), CZ absolute, the points in bindata/data.bin as little-endian float64 (D) or
// float32 (F) metres, x fastest, the first row the smallest y. Offsets are the first
// cell's centre, so the grid's origin is Offset - Increment / 2 (m -> mm). When
// main.xml gives MD5ChecksumPointData, data.bin must match it.
#pragma once

#include <string>

#include "raycast/zmap.h"

namespace scallop {

// Throws InputError(path, ...) naming what is missing or inconsistent.
ZMap readHeightsX3p(const std::string& path);

}  // namespace scallop
