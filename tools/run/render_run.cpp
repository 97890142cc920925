#include "tools/run/render_run.h"

#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "analysis/surface_metrology.h"
#include "base/input_error.h"
#include "tools/io/file_names.h"
#include "tools/io/height16_reader.h"
#include "tools/io/height_export.h"
#include "tools/io/x3p_reader.h"
#include "tools/run/band_files.h"
#include "tools/run/report.h"
#include "tools/run/stats_document.h"

namespace scallop {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Every band of the run in `dir`, each checked (description, fingerprint, size, MD5),
// copied into one map.
ZMap readBands(const std::string& dir) {
  const std::string first = bandDescriptionPath(dir, 0);
  if (!fs::exists(first))
    throw InputError(dir,
                     "a folder without band-0.json: expected the band files of `scallop "
                     "simulate --bands` (or give a height file)");
  const json reference = readBandDescription(first, 0);
  GridSpec grid;
  int64_t bands = 0, bandRows = 0;
  try {
    grid = gridFromJson(reference.at("run").at("grid"));
    bands = reference.at("run").at("bands").get<int64_t>();
    bandRows = reference.at("run").at("band_rows").get<int64_t>();
  } catch (const json::exception& e) {
    throw InputError(first, std::string("damaged band description: ") + e.what());
  }
  if (bands < 1 || bandRows < 1) throw InputError(first, "damaged band description: no bands");
  ZMap map(grid, NAN);
  for (int64_t b = 0; b < bands; ++b) {
    const std::string path = bandDescriptionPath(dir, b);
    if (!fs::exists(path))
      throw InputError(path, fmt::format("missing: band {} of {} was not computed; {}", b, bands,
                                         bandCommand(dir, b, reference)));
    const json doc = readBandDescription(path, b);
    if (doc.at("fingerprint") != reference.at("fingerprint"))
      throw InputError(path, "belongs to another run than band-0.json (fingerprint differs)");
    checkBandRawSize(dir, b, doc);
    // Image rows [b * bandRows, min(ny, (b + 1) * bandRows)) from the top (largest y).
    const int64_t end = std::min(grid.ny, (b + 1) * bandRows), begin = b * bandRows;
    ZMap band(grid.rows(grid.ny - end, grid.ny - begin), 0.0);
    readBandRaw(dir, b, doc, band);
    for (int64_t j = 0; j < band.ny(); ++j)
      for (int64_t i = 0; i < grid.nx; ++i) map.at(i, band.grid().offsetJ + j) = band.at(i, j);
  }
  return map;
}

}  // namespace

ZMap readAnyHeightMap(const std::string& path) {
  if (fs::is_directory(path)) return readBands(path);
  const std::string ext = lowerExtension(path);
  if (!fs::exists(path)) throw InputError(path, "no such file");
  if (ext == ".x3p") return readHeightsX3p(path);
  if (ext == ".png" || ext == ".tif" || ext == ".tiff") return readHeights16(path);
  if (ext == ".gsf" || ext == ".exr") return readHeightFile(path);
  throw InputError(path,
                   "expected a height map: .gsf, .exr, .x3p, a 16-bit .png/.tif/.tiff "
                   "written by scallop export, or a folder of band files");
}

RenderSummary runRender(const RenderRequest& request) {
  checkRenderOptions(request.options);
  if (lowerExtension(request.output) != ".png")
    throw InputError("-o", "expected a file name ending in .png, got \"" + request.output + "\"");
  const ZMap map = readAnyHeightMap(request.heights);
  const CellRegion region = statsRegion(map.grid(), request.region, "--region");
  return writeRenderPng(map, region, request.output, request.options, "--region");
}

}  // namespace scallop
