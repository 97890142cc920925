// What each cell of a coloured picture of a height map shows (preview.png,
// tools/render/preview_png.h, which `export --hillshade --colour` also draws): material
// some move cut, the stock as it started (no move reached the cell), or no material at
// all (the cell's line misses the stock: NaN). The last two are told apart in the
// legend, so that a blank's material left standing does not read as "nothing there".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tools/render/png_canvas.h"
#include "tools/render/relief_shading.h"

namespace scallop {

enum class CellKind : uint8_t { Cut, NotCut, NoMaterial };

// The kind of every cell of `raster` (a reduced map, NaN where there is no material).
// A cell is not cut when it is at or above `uncutHeight` (a box stock's top; NaN:
// none), or with `stock` (the stock's own heights reduced the same way: a solid or a
// previous map) when it is not below the stock's height there.
std::vector<CellKind> cellKinds(const HeightRaster& raster, double uncutHeight,
                                const HeightRaster* stock = nullptr);

// Not cut: a neutral grey, apart from viridis's saturated colours, lit by the relief
// (a flat stock top keeps exactly this grey). No material: the page's white.
constexpr png::Rgb kNotCutColour{185, 185, 185};
constexpr png::Rgb kNoMaterialColour{255, 255, 255};

// The legend's line for each kind that occurs (none for Cut), with its swatch colour.
struct CellLegendLine {
  png::Rgb colour;
  std::string text;
};
std::vector<CellLegendLine> cellLegend(const std::vector<CellKind>& kinds);

}  // namespace scallop
