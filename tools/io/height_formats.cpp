// The height-format table (height_formats.h).
#include "tools/io/height_formats.h"

#include "base/input_error.h"
#include "tools/io/file_names.h"
#include "tools/io/height_export.h"
#include "tools/io/height_images.h"
#include "tools/io/x3p_reader.h"
#include "tools/io/x3p_writer.h"

namespace scallop {

namespace {

// The writers' and readers' own signatures, brought to the table's.
void writeExr(const ZMap& map, const std::string& path, const std::string&,
              const std::string& frame) {
  writeHeightsExr(map, path, frame);
}
void writeGsf(const ZMap& map, const std::string& path, const std::string& title,
              const std::string& frame) {
  writeHeightsGsf(map, path, title, frame);
}
// X3P has no field for a frame: it goes into the comment, as text.
void writeX3p(const ZMap& map, const std::string& path, const std::string& title,
              const std::string& frame) {
  writeHeightsX3p(map, path, frame.empty() ? title : title + "; heights in the frame: " + frame);
}
ZMap readX3p(const std::string& path, std::string* frame) {
  if (frame) frame->clear();
  return readHeightsX3p(path);
}
void write16(const ZMap& map, const std::string& path, const std::string&,
             const std::string& frame) {
  writeHeights16(map, path, frame);
}

}  // namespace

const std::vector<HeightFormat>& heightFormats() {
  static const std::vector<HeightFormat> table = {
      {".x3p", "ISO 25178-72 X3P", writeX3p, readX3p, "float64 m", false, true},
      {".png", "16-bit PNG", write16, nullptr, "16-bit levels of mm", true, true},
      {".tif", "16-bit TIFF", write16, nullptr, "16-bit levels of mm", true, true},
      {".tiff", "16-bit TIFF", write16, nullptr, "16-bit levels of mm", true, true},
      {".gsf", "Gwyddion Simple Field", writeGsf, readHeightsGsf, "float32 m", true, true},
      {".exr", "OpenEXR", writeExr, readHeightsExr, "float32 mm", true, true},
  };
  return table;
}

const HeightFormat* findHeightFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  for (const HeightFormat& f : heightFormats())
    if (ext == f.extension) return &f;
  return nullptr;
}

std::string heightExtensions(bool reading) {
  std::vector<const char*> names;
  for (const HeightFormat& f : heightFormats())
    if (!reading || f.read) names.push_back(f.extension);
  std::string text;
  for (size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + std::string(names[k]);
  return text;
}

const HeightFormat& heightFormatOf(const std::string& path, bool reading) {
  const HeightFormat* f = findHeightFormat(path);
  if (f && (!reading || f->read)) return *f;
  throw InputError(path, reading ? "expected a height map scallop reads: a " +
                                       heightExtensions(true) + " file"
                                 : "expected a file name ending in " + heightExtensions(false));
}

}  // namespace scallop
