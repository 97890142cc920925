#include "tools/render/colour_map.h"

#include <cmath>

#include "base/input_error.h"
#include "tools/render/height_colours.h"

namespace scallop {

ColourMap parseColourMap(const std::string& name, const std::string& where) {
  if (name == "viridis") return ColourMap::kViridis;
  if (name == "grey" || name == "gray") return ColourMap::kGrey;
  throw InputError(where, "expected viridis or grey, got \"" + name + "\"");
}

const char* colourMapName(ColourMap map) {
  return map == ColourMap::kGrey ? "grey" : "viridis";
}

png::Rgb colourAt(ColourMap map, double t) {
  if (map == ColourMap::kViridis) return viridis(t);
  if (!(t > 0)) t = 0;  // also catches NaN
  if (t > 1) t = 1;
  const auto v = uint8_t(std::lround(40 + 195 * t));
  return {v, v, v};
}

}  // namespace scallop
