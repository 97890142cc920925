#include "tools/io/height16_reader.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "base/input_error.h"

namespace scallop {

ZMap readHeights16(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, "cannot read the image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 1 || spec.format != OIIO::TypeDesc::UINT16)
    throw InputError(path,
                     "expected a 16-bit single-channel height image written by scallop "
                     "(`scallop export --to F.png|F.tif`)");
  const std::string description = spec.get_string_attribute("ImageDescription");
  double offset = 0, scale = 0, spacing = 0, cx = 0, cy = 0;
  long long nx = 0, ny = 0;
  const size_t at = description.find("z_offset_mm = ");
  const size_t grid = description.find(" cells of ");
  if (at == std::string::npos || grid == std::string::npos ||
      std::sscanf(description.c_str() + at, "z_offset_mm = %lf; z_scale_mm = %lf; %lld x %lld",
                  &offset, &scale, &nx, &ny) != 4 ||
      std::sscanf(description.c_str() + grid,
                  " cells of %lf mm, first cell centre at (%lf, %lf) mm", &spacing, &cx, &cy) != 3)
    throw InputError(path,
                     "no scallop height description in ImageDescription (\"z_mm = "
                     "z_offset_mm + z_scale_mm * value; ...\"): not a height image "
                     "written by scallop");
  if (nx != spec.width || ny != spec.height || !(spacing > 0) || !std::isfinite(offset) ||
      !std::isfinite(scale) || !std::isfinite(cx) || !std::isfinite(cy))
    throw InputError(path, fmt::format("inconsistent description: {} x {} cells of {} mm in an "
                                       "image of {} x {} pixels",
                                       nx, ny, spacing, spec.width, spec.height));
  const bool hasVoid = description.find("value 0: no material") != std::string::npos;
  std::vector<uint16_t> pixels(size_t(nx) * size_t(ny));
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, pixels.data()))
    throw InputError(path, "cannot read the image: " + in->geterror());
  GridSpec g;
  g.spacing = spacing, g.nx = nx, g.ny = ny;
  // Row 0 is the largest y: the first cell centre given is that of (0, ny - 1).
  g.originX = cx - 0.5 * spacing;
  g.originY = cy - (double(ny) - 0.5) * spacing;
  ZMap map(g, 0.0);
  for (int64_t row = 0; row < ny; ++row)
    for (int64_t i = 0; i < nx; ++i) {
      const uint16_t v = pixels[size_t(row * nx + i)];
      map.at(i, ny - 1 - row) = hasVoid && v == 0 ? NAN : offset + scale * double(v);
    }
  return map;
}

}  // namespace scallop
