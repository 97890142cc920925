#include "tools/io/job_cutter_shapes.h"

#include <nlohmann/json.hpp>
#include <vector>

#include "base/input_error.h"
#include "sweep/apt_cutter.h"
#include "sweep/cutter_shapes.h"
#include "tools/io/job_fields.h"

namespace scallop {

using nlohmann::json;
using namespace jobfield;

namespace {

const double kZero = 0;

// The keys of one shape: its own and the teeth keys, "type" always.
void rejectOtherKeys(const json& tool, std::set<std::string> keys,
                     const std::set<std::string>& teethKeys, const std::string& f) {
  keys.insert("type");
  keys.insert(teethKeys.begin(), teethKeys.end());
  rejectUnknownKeys(tool, keys, f);
}

// A length that may be left out (0 then: the builder's default or "not given").
double optionalLength(const json& tool, const char* key, const std::string& f) {
  return number(tool, key, f + "." + key, &kZero);
}

double required(const json& tool, const char* key, const std::string& f) {
  return number(tool, key, f + "." + key);
}

// "segments": [{"to": [rho, s]}, {"to": [rho, s], "arc_radius": R}, ...] from (0, 0).
std::vector<ProfileSegment> parseSegments(const json& tool, const std::string& f) {
  const std::string sf = f + ".segments";
  if (!tool.contains("segments") || !tool.at("segments").is_array() || tool.at("segments").empty())
    throw InputError(sf,
                     "expected a list of segments from the tip up, e.g. [{\"to\": [3, 0]}, "
                     "{\"to\": [4, 2], \"arc_radius\": 2.5}], each from where the last "
                     "ended ([0, 0] first)");
  std::vector<ProfileSegment> chain;
  double rho = 0, s = 0;
  const json& list = tool.at("segments");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string itemField = sf + "[" + std::to_string(i) + "]";
    const json& item = list[i];
    if (!item.is_object()) throw InputError(itemField, "expected {\"to\": [rho, s]} (mm)");
    rejectUnknownKeys(item, {"to", "arc_radius"}, itemField);
    if (!item.contains("to") || !item.at("to").is_array() || item.at("to").size() != 2 ||
        !item.at("to")[0].is_number() || !item.at("to")[1].is_number())
      throw InputError(itemField + ".to", "expected the segment's end [rho, s]: two numbers, mm");
    ProfileSegment seg;
    seg.rho0 = rho, seg.s0 = s;
    seg.rho1 = item.at("to")[0].get<double>();
    seg.s1 = item.at("to")[1].get<double>();
    seg.arcRadius = number(item, "arc_radius", itemField + ".arc_radius", &kZero);
    if (item.contains("arc_radius") && !(seg.arcRadius > 0))
      throw InputError(itemField + ".arc_radius", "must be > 0 mm (leave it out for a line)");
    chain.push_back(seg);
    rho = seg.rho1, s = seg.s1;
  }
  return chain;
}

}  // namespace

const std::set<std::string>& shapedCutterTypeNames() {
  static const std::set<std::string> names = {"taper_ball", "taper_bull",   "cone",
                                              "barrel",     "taper_barrel", "oval",
                                              "lens",       "profile",      "apt"};
  return names;
}

Cutter parseShapedCutter(const json& tool, const std::string& type,
                         const std::set<std::string>& teethKeys, const std::string& f) {
  if (type == "taper_ball") {
    rejectOtherKeys(tool, {"tip_radius", "taper_deg", "flute_length", "flute_diameter"}, teethKeys,
                    f);
    TaperBallShape shape;
    shape.tipRadius = required(tool, "tip_radius", f);
    shape.taperDeg = required(tool, "taper_deg", f);
    shape.fluteLength = optionalLength(tool, "flute_length", f);
    shape.fluteDiameter = optionalLength(tool, "flute_diameter", f);
    return cutterOfChain(CutterType::TaperBall, taperBallChain(shape, f), f);
  }
  if (type == "taper_bull") {
    rejectOtherKeys(
        tool, {"tip_diameter", "corner_radius", "taper_deg", "flute_length", "flute_diameter"},
        teethKeys, f);
    TaperBullShape shape;
    shape.tipDiameter = required(tool, "tip_diameter", f);
    shape.cornerRadius = required(tool, "corner_radius", f);
    shape.taperDeg = required(tool, "taper_deg", f);
    shape.fluteLength = optionalLength(tool, "flute_length", f);
    shape.fluteDiameter = optionalLength(tool, "flute_diameter", f);
    return cutterOfChain(CutterType::TaperBull, taperBullChain(shape, f), f);
  }
  if (type == "cone") {
    rejectOtherKeys(tool, {"angle_deg", "tip_diameter", "diameter", "flute_length"}, teethKeys, f);
    ConeShape shape;
    shape.angleDeg = required(tool, "angle_deg", f);
    shape.tipDiameter = optionalLength(tool, "tip_diameter", f);
    shape.diameter = required(tool, "diameter", f);
    shape.fluteLength = required(tool, "flute_length", f);
    return cutterOfChain(CutterType::Cone, coneChain(shape, f), f);
  }
  if (type == "barrel") {
    rejectOtherKeys(tool,
                    {"diameter", "form_radius", "tip_radius", "equator_height", "flute_length"},
                    teethKeys, f);
    BarrelShape shape;
    shape.diameter = required(tool, "diameter", f);
    shape.formRadius = required(tool, "form_radius", f);
    shape.tipRadius = optionalLength(tool, "tip_radius", f);
    shape.fluteLength = required(tool, "flute_length", f);
    shape.equatorHeight = tool.contains("equator_height") ? required(tool, "equator_height", f)
                                                          : shape.fluteLength / 2;
    return cutterOfChain(CutterType::Barrel, barrelChain(shape, f), f);
  }
  if (type == "taper_barrel") {
    rejectOtherKeys(
        tool, {"tip_radius", "form_radius", "taper_deg", "reference_diameter", "flute_length"},
        teethKeys, f);
    TaperBarrelShape shape;
    shape.tipRadius = required(tool, "tip_radius", f);
    shape.formRadius = required(tool, "form_radius", f);
    shape.taperDeg = required(tool, "taper_deg", f);
    shape.referenceDiameter = required(tool, "reference_diameter", f);
    shape.fluteLength = required(tool, "flute_length", f);
    return cutterOfChain(CutterType::TaperBarrel, taperBarrelChain(shape, f), f);
  }
  if (type == "oval") {
    rejectOtherKeys(tool, {"diameter", "form_radius", "tip_radius", "flute_length"}, teethKeys, f);
    OvalShape shape;
    shape.diameter = required(tool, "diameter", f);
    shape.formRadius = required(tool, "form_radius", f);
    shape.tipRadius = required(tool, "tip_radius", f);
    shape.fluteLength = required(tool, "flute_length", f);
    return cutterOfChain(CutterType::Oval, ovalChain(shape, f), f);
  }
  if (type == "lens") {
    rejectOtherKeys(tool, {"diameter", "form_radius", "corner_radius", "flute_length"}, teethKeys,
                    f);
    LensShape shape;
    shape.diameter = required(tool, "diameter", f);
    shape.formRadius = required(tool, "form_radius", f);
    shape.cornerRadius = optionalLength(tool, "corner_radius", f);
    shape.fluteLength = required(tool, "flute_length", f);
    return cutterOfChain(CutterType::Lens, lensChain(shape, f), f);
  }
  if (type == "profile") {
    rejectOtherKeys(tool, {"segments"}, teethKeys, f);
    return cutterOfChain(CutterType::Profile, parseSegments(tool, f), f);
  }
  if (type == "apt") {
    rejectOtherKeys(tool, {"d", "r", "e", "f", "a", "b", "h"}, teethKeys, f);
    AptCutterValues v;
    v.d = required(tool, "d", f);
    v.r = required(tool, "r", f);
    v.e = required(tool, "e", f);
    v.f = required(tool, "f", f);
    v.a = required(tool, "a", f);
    v.b = required(tool, "b", f);
    v.h = required(tool, "h", f);
    return aptCutter(v, f);
  }
  throw InputError(f + ".type", "unknown cutter type \"" + type + "\"");
}

json profileSegmentsToJson(const CutterProfile& profile) {
  json segments = json::array();
  for (const ProfileSegment& seg : profile.segments()) {
    json item = {{"from", {seg.rho0, seg.s0}}, {"to", {seg.rho1, seg.s1}}};
    if (seg.arcRadius > 0) {
      item["arc_radius"] = seg.arcRadius;
      item["centre"] = {seg.centreRho, seg.centreS};
    }
    segments.push_back(item);
  }
  return segments;
}

}  // namespace scallop
