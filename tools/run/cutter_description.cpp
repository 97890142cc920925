#include "tools/run/cutter_description.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "base/input_error.h"
#include "tools/io/job_cutter_shapes.h"
#include "tools/io/job_cutters.h"
#include "tools/render/cutter_svg.h"
#include "tools/render/svg_plot.h"

namespace scallop {

using nlohmann::json;

namespace {

CutterProfile profileOf(const Cutter& cutter) {
  return cutter.general() ? *cutter.profile : CutterProfile::of(cutter);
}

}  // namespace

Cutter cutterFromArgument(const std::string& argument) {
  const bool inline_ = !argument.empty() && argument.front() == '{';
  const std::string source = inline_ ? "the cutter argument" : argument;
  std::string text = argument;
  if (!inline_) {
    std::ifstream in(argument);
    if (!in) throw InputError(argument, "cannot open the cutter or job file");
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(source, std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object())
    throw InputError(source, "expected a cutter object {\"type\": ...} or a job with \"tool\"");
  if (doc.contains("tool") && !doc.contains("type")) {
    if (!doc.at("tool").is_object())
      throw InputError(source + ": tool", "expected a cutter object");
    return parseCutter(doc.at("tool"), source + ": tool");
  }
  return parseCutter(doc, source + ": tool");
}

json cutterDocument(const Cutter& cutter) {
  const CutterProfile profile = profileOf(cutter);
  json doc = cutterToJson(cutter);
  doc["max_radius"] = profile.maxRadius();
  doc["segments"] = profileSegmentsToJson(profile);
  return doc;
}

std::string cutterTable(const Cutter& cutter) {
  const CutterProfile profile = profileOf(cutter);
  std::string out = fmt::format(
      "{} cutter: max radius {:.10g} mm, flute length L {:.10g} mm, {} segments\n",
      toString(cutter.type), profile.maxRadius(), profile.fluteLength(), profile.segments().size());
  out += "  segment  from (rho, s) mm            to (rho, s) mm              arc radius, centre\n";
  size_t i = 0;
  for (const ProfileSegment& seg : profile.segments()) {
    out += fmt::format("  {:>7}  ({:>11.6f}, {:>11.6f})  ({:>11.6f}, {:>11.6f})  ", i++, seg.rho0,
                       seg.s0, seg.rho1, seg.s1);
    out += seg.arcRadius > 0 ? fmt::format("arc {:.10g} about ({:.6f}, {:.6f})\n", seg.arcRadius,
                                           seg.centreRho, seg.centreS)
                             : "line\n";
  }
  return out;
}

json cutterShapesDocument() {
  json doc = json::array();
  for (const CutterShape& shape : cutterShapes()) {
    json keys = json::array(), pictures = json::array();
    for (const CutterKey& key : shape.keys)
      keys.push_back({{"name", key.name}, {"meaning", key.meaning}, {"required", key.required}});
    for (const CutterPicture& picture : shape.pictures)
      pictures.push_back({{"file", std::string("docs/images/cutters/") + picture.file + ".svg"},
                          {"title", picture.title},
                          {"tool", json::parse(picture.tool)}});
    doc.push_back(
        {{"type", shape.type}, {"summary", shape.summary}, {"keys", keys}, {"pictures", pictures}});
  }
  return doc;
}

std::string cutterShapesText() {
  std::string out;
  for (const CutterShape& shape : cutterShapes()) {
    out += fmt::format("{}: {}\n", shape.type, shape.summary);
    for (const CutterKey& key : shape.keys)
      out +=
          fmt::format("  {:<19}{}{}\n", key.name, key.meaning, key.required ? "" : " [optional]");
    for (const CutterPicture& picture : shape.pictures)
      out += fmt::format("  e.g. {}\n", picture.tool);
  }
  return out;
}

std::string cutterPictureLines() {
  std::string out;
  for (const CutterShape& shape : cutterShapes())
    for (const CutterPicture& picture : shape.pictures)
      out += fmt::format("{}\t{}\t{}\n", picture.file, picture.title, picture.tool);
  return out;
}

void writeCutterSvg(const Cutter& cutter, const std::string& title, const std::string& path) {
  writeSvgFile(path, cutterProfileSvg(cutter, title));
}

}  // namespace scallop
