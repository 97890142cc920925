// Cells without material (NaN) in the pictures of a height map: the relief's slopes
// beside them are those of the surface (one-sided differences, exact on a plane), the
// texture's are finite, the colour range leaves them out; and each cell's kind (cut,
// not cut, no material) comes from the stock's height, with a legend line per kind.
#include "tools/render/map_cells.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/sampled_field.h"
#include "tools/render/height_colours.h"
#include "tools/render/relief_shading.h"

namespace scallop {
namespace {

// A plane z = 0.01 x - 0.02 y over 30 x 20 cells of 0.1 mm with a hole (no material)
// of radius 0.6 mm at (1.5, 1).
ZMap planeWithHole() {
  return sampledField(0, 0, 30, 20, 0.1, [](double x, double y) {
    return std::hypot(x - 1.5, y - 1) < 0.6 ? NAN : 0.01 * x - 0.02 * y;
  });
}

TEST(MapCells, SlopesBesideCellsWithoutMaterialAreTheSurfaces) {
  const HeightRaster raster = reduceMap(planeWithHole(), 1600);
  const Slopes s = slopes(raster);
  const Slopes texture = textureSlopes(raster, 12);
  int holes = 0;
  for (size_t c = 0; c < raster.z.size(); ++c) {
    if (std::isnan(raster.z[c])) {
      ++holes;
      continue;
    }
    EXPECT_NEAR(s.dzdx[c], 0.01, 1e-12) << c;
    EXPECT_NEAR(s.dzdy[c], -0.02, 1e-12) << c;
    EXPECT_TRUE(std::isfinite(texture.dzdx[c]) && std::isfinite(texture.dzdy[c])) << c;
  }
  EXPECT_GT(holes, 80);
  const auto [low, high] = robustRange(raster);
  EXPECT_TRUE(std::isfinite(low) && std::isfinite(high));
  EXPECT_LT(low, high);
}

TEST(MapCells, KindsComeFromTheStocksHeights) {
  HeightRaster map, stock;
  map.w = stock.w = 4;
  map.h = stock.h = 1;
  map.z = {NAN, -1, 2, 5};
  stock.z = {NAN, 0, 2, 6};  // cell 2 is still at the stock, 1 and 3 are cut
  const std::vector<CellKind> kinds = cellKinds(map, NAN, &stock);
  EXPECT_EQ(kinds, (std::vector<CellKind>{CellKind::NoMaterial, CellKind::Cut, CellKind::NotCut,
                                          CellKind::Cut}));
  // A box stock's top alone: cells at it are not cut.
  EXPECT_EQ(cellKinds(map, 5)[3], CellKind::NotCut);
  EXPECT_EQ(cellKinds(map, 5)[2], CellKind::Cut);
  const std::vector<CellLegendLine> legend = cellLegend(kinds);
  ASSERT_EQ(legend.size(), 2u);
  EXPECT_EQ(legend[0].text.rfind("not cut", 0), 0u);
  EXPECT_EQ(legend[1].text.rfind("no material", 0), 0u);
  EXPECT_TRUE(cellLegend(cellKinds(map, NAN)).size() == 1);  // no stock: no "not cut"
}

}  // namespace
}  // namespace scallop
