// Height formats: one entry an extension, with its writer, its reader (if scallop reads
// it back) and what the file keeps. Every command that writes or reads a height map by
// its file name goes through this table: `scallop export` and `stats`, simulate's and
// merge's outputs (their names are fixed: heights.exr, heights.gsf), and the Python
// module's read_heights / write_heights. Adding a format: its writer (and reader) as a
// file pair in tools/io, then one entry in height_formats.cpp (docs/extending.md).
#pragma once

#include <string>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

struct HeightFormat {
  const char* extension;  // lower case, with its dot: ".gsf"
  const char* name;       // for people: "Gwyddion Simple Field"
  // Writes `map` to `path` atomically (nothing is left on failure). `title` goes into
  // the formats that carry one; `frame` (GridFrame::describe(), empty for a map seen
  // from above) says which frame the heights are in.
  void (*write)(const ZMap& map, const std::string& path, const std::string& title,
                const std::string& frame);
  // Reads a file of this format back; `frame`, when given, receives the frame the file
  // names (empty when it names none). Null: scallop does not read the format.
  ZMap (*read)(const std::string& path, std::string* frame);
  // What the file keeps.
  const char* heights;    // the stored values: "float32 mm", "16-bit levels of mm", ...
  bool keepsFrame;        // the frame, as `read` returns it (or as text, without `read`)
  bool keepsNoMaterial;   // cells without material (NaN) stay NaN
};

// The table, in the order --help lists the extensions.
const std::vector<HeightFormat>& heightFormats();

// The entry of `path`'s extension (any case), or null.
const HeightFormat* findHeightFormat(const std::string& path);

// The entry of `path`'s extension, one with a reader when `reading`; else throws
// InputError(path, ...) naming the extensions expected.
const HeightFormat& heightFormatOf(const std::string& path, bool reading);

// ".x3p, .png, .tif, .tiff, .gsf or .exr": the extensions (those with a reader when
// `reading`), for messages and --help.
std::string heightExtensions(bool reading);

}  // namespace scallop
