// `scallop export FILE.gsf|FILE.exr --to OUT`: converts a height map written by scallop
// into the format OUT's extension names: .x3p (ISO 25178-72, tools/io/x3p_writer.h),
// .png / .tif / .tiff (16-bit grey with the height scale in the metadata,
// tools/io/height_export.h), .gsf / .exr (tools/io/height_images.h), or .csv (a --profile's
// samples and roughness). With --hillshade, .png is a hill-shaded picture for people
// (tools/render/hillshade_png.h) of the map or a --region of it.
#pragma once

namespace scallop {}  // namespace scallop
