// Height images: the files `scallop simulate` writes into its output folder
// (CONVENTIONS.md, "Height images written by simulate"), and readers for two of them.
//
// Every image is north up: image row 0 (the first row stored) is the *largest* y,
// i.e. ZMap row j = ny - 1, so the picture is the part seen from above with +X to
// the right. All writers go through AtomicFile, so a failure never leaves a partial
// file, and they throw scallop::InputError naming the path on any error.
//
// heights.exr  OpenEXR, one float32 channel "Z" = absolute height in mm, zip
//              compressed. The grid is in the header as double attributes
//              "scallop:origin_x", "scallop:origin_y" (the grid's minimum corner, mm)
//              and "scallop:spacing_mm" (cell side), plus a human "ImageDescription".
//
// heights.gsf  Gwyddion Simple Field: the magic line "Gwyddion Simple Field 1.0",
//              "Key = Value" lines (XRes, YRes, XReal, YReal, XOffset, YOffset,
//              XYUnits = m, ZUnits = m, Title), 1-4 NUL bytes so the header length is
//              a multiple of 4, then XRes*YRes little-endian float32 heights in metres,
//              row by row, first row = largest y. Gwyddion draws the first row at the
//              top, so the picture matches heights.exr; note that Gwyddion's own y
//              axis points down from YOffset, so a Gwyddion y coordinate yg maps to
//              our y = 2*YOffset + YReal - yg (in metres).
//
// preview.png, the picture for people, is drawn by tools/render/preview_png.h.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "raycast/zmap.h"

namespace scallop {

// `frame` (GridFrame::describe(), empty for a map seen from above) says which frame the
// heights are in: EXR attribute scallop:frame, GSF header field ScallopFrame.
void writeHeightsExr(const ZMap& map, const std::string& path, const std::string& frame = "");
void writeHeightsGsf(const ZMap& map, const std::string& path, const std::string& title,
                     const std::string& frame = "");

// Streams heights.exr and heights.gsf for a map too large to hold, band by band from
// the top (image row 0, the largest y) down. The EXR is tiled (tileHeight rows of
// 256 columns), so each band but the last must have a multiple of tileHeight rows.
// Both files are temporary until close() renames them into place; an exception or
// destruction before that leaves nothing behind.
class HeightStreamWriter {
 public:
  HeightStreamWriter(const GridSpec& grid, const std::string& exrPath, const std::string& gsfPath,
                     const std::string& title, int tileHeight, const std::string& frame = "");
  ~HeightStreamWriter();
  HeightStreamWriter(const HeightStreamWriter&) = delete;
  HeightStreamWriter& operator=(const HeightStreamWriter&) = delete;

  // The next band: rows grid.rows(j0, j1) of the full grid (ZMap order, j = 0 at the
  // band's smallest y) directly below the rows written so far.
  void append(const ZMap& band);
  void close();

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// Read back what the writers above produce (also any single-channel float image or
// GSF with the same metadata). The GridSpec comes from the metadata: for GSF,
// spacing = XReal / XRes (m -> mm) and origin = (XOffset, YOffset). Heights are
// float32 in the files, so they round-trip to float precision only.
// Throw InputError(path, ...) for unreadable or inconsistent files. `frame`, when given,
// receives the frame the heights are in (the EXR attribute scallop:frame, the GSF field
// ScallopFrame; empty for a map seen from above).
ZMap readHeightsExr(const std::string& path, std::string* frame = nullptr);
ZMap readHeightsGsf(const std::string& path, std::string* frame = nullptr);

}  // namespace scallop
