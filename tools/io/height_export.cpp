// Reading by extension, 16-bit PNG/TIFF and CSV profile export (height_export.h).
#include "tools/io/height_export.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "base/input_error.h"
#include "base/version.h"
#include "tools/io/atomic_file.h"
#include "tools/io/file_names.h"
#include "tools/io/height_formats.h"
#include "tools/io/height_images.h"

namespace scallop {

ZMap readHeightFile(const std::string& path, std::string* frame) {
  if (!std::filesystem::exists(path)) throw InputError(path, "no such file");
  return heightFormatOf(path, true).read(path, frame);
}

void writeHeights16(const ZMap& map, const std::string& path, const std::string& frame) {
  const std::string ext = lowerExtension(path);
  const char* format = ext == ".png" ? "png" : (ext == ".tif" || ext == ".tiff") ? "tiff" : nullptr;
  if (!format) throw InputError(path, "expected a .png, .tif or .tiff file name");
  const GridSpec& g = map.grid();
  if (g.nx <= 0 || g.ny <= 0 || g.nx > INT32_MAX || g.ny > INT32_MAX)
    throw InputError(path, "the height map is empty or too large for an image");
  // A map with cells without material (NaN) keeps the value 0 for them, its heights
  // from 1 up; without, every value is a height (the files of maps seen from above).
  const bool hasVoid = std::any_of(map.heights().begin(), map.heights().end(),
                                   [](double z) { return std::isnan(z); });
  const double first = hasVoid ? 1 : 0, levels = 65535 - first;
  const double zMin0 = map.minHeight(), zMax = map.maxHeight();
  // A flat map still gets a positive scale so that offset + scale * v stays valid.
  const double scale = zMax > zMin0 ? (zMax - zMin0) / levels : 1e-6;
  // z = zMin + scale * value: value `first` is the lowest height.
  const double zMin = zMin0 - first * scale;
  std::vector<uint16_t> pixels(size_t(g.cells()));
  for (int64_t row = 0; row < g.ny; ++row)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double z = map.at(i, g.ny - 1 - row);
      const double v = std::clamp(std::round((z - zMin0) / scale) + first, first, 65535.0);
      pixels[size_t(row * g.nx + i)] = std::isnan(z) ? 0 : uint16_t(v);
    }
  OIIO::ImageSpec spec(int(g.nx), int(g.ny), 1, OIIO::TypeDesc::UINT16);
  spec.channelnames = {"Z"};
  spec.attribute("ImageDescription",
                 fmt::format("scallop height map: z_mm = z_offset_mm + z_scale_mm * value; "
                             "z_offset_mm = {}; z_scale_mm = {}; {} x {} cells of {} mm, "
                             "first cell centre at ({}, {}) mm; row 0 is the largest y{}{}",
                             zMin, scale, g.nx, g.ny, g.spacing, g.cellCentreX(0),
                             g.cellCentreY(g.ny - 1), hasVoid ? "; value 0: no material" : "",
                             frame.empty() ? "" : "; frame: " + frame));
  if (!frame.empty()) spec.attribute("scallop:frame", frame);
  spec.attribute("scallop:z_offset_mm", fmt::format("{}", zMin));
  spec.attribute("scallop:z_scale_mm", fmt::format("{}", scale));
  spec.attribute("scallop:origin_x", fmt::format("{}", g.originX));
  spec.attribute("scallop:origin_y", fmt::format("{}", g.originY));
  spec.attribute("scallop:spacing_mm", fmt::format("{}", g.spacing));
  if (hasVoid) spec.attribute("scallop:no_material_value", "0");
  spec.attribute("Software", std::string("scallop ") + kScallopVersion);
  writeFileAtomically(path, [&](const std::string& temp) {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) throw InputError(path, std::string("image writer unavailable: ") + OIIO::geterror());
    if (!out->open(temp, spec) || !out->write_image(OIIO::TypeDesc::UINT16, pixels.data()) ||
        !out->close())
      throw InputError(path, "cannot write the image: " + out->geterror());
  });
}

void writeProfileCsv(const Profile& p, const RoughnessStats* r, const std::string& path) {
  std::string text = "distance_mm,x_mm,y_mm,z_mm,roughness_mm\n";
  for (size_t k = 0; k < p.height.size(); ++k) {
    text += fmt::format("{},{},{},{},", double(k) * p.stepMm, p.xAt(int64_t(k)), p.yAt(int64_t(k)),
                        p.height[k]);
    if (r && std::isfinite(r->roughness[k])) text += fmt::format("{}", r->roughness[k]);
    text += "\n";
  }
  writeTextAtomically(path, text, "the profile");
}

}  // namespace scallop
