// The cutter-shape table (job_cutter_shapes.h).
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

// Ball, flat and bull: a radius (and a bull's corner radius), L defaulting to 4 R.
Cutter revolved(CutterType type, const CutterKeyValues& k, const std::string& f) {
  if (k.given("flute_length") && !(k["flute_length"] > 0))
    throw InputError(f + ".flute_length", "must be > 0 mm");
  return Cutter::make(type, k["radius"], k["corner_radius"], k["flute_length"], f);
}

// Keys several shapes share, worded once.
const CutterKey kFluteLength{"flute_length", "L: the flutes' height above the tip, mm", true};
const CutterKey kFluteLengthOr{
    "flute_length", "L, mm; or flute_diameter: where the flank reaches that diameter, mm", false};
const CutterKey kFluteDiameter{"flute_diameter", "the flank's diameter at its top, mm", false};
const CutterKey kTaper{"taper_deg", "the flank's angle to the axis, per side, degrees (0, 45]",
                       true};

}  // namespace

double CutterKeyValues::operator[](const std::string& key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? 0.0 : it->second;
}

const std::vector<CutterShape>& cutterShapes() {
  static const std::vector<CutterShape> table = {
      {"ball",
       "ball end mill: a hemisphere of radius R on a cylinder",
       {{"radius", "R, mm (> 0)", true}, {"flute_length", "L, mm (default 4 R)", false}},
       {{"ball", "ball R3", R"({"type": "ball", "radius": 3, "flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         return revolved(CutterType::Ball, k, f);
       }},
      {"flat",
       "flat end mill: a cylinder of radius R",
       {{"radius", "R, mm (> 0)", true}, {"flute_length", "L, mm (default 4 R)", false}},
       {{"flat", "flat R3", R"({"type": "flat", "radius": 3, "flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         return revolved(CutterType::Flat, k, f);
       }},
      {"bull",
       "bull-nose (torus, filleted) end mill: radius R, corner radius r",
       {{"radius", "R, mm (> 0)", true},
        {"corner_radius", "r: the torus's tube radius, mm (0 < r < R)", true},
        {"flute_length", "L, mm (default 4 R)", false}},
       {{"bull", "bull R3 r1",
         R"({"type": "bull", "radius": 3, "corner_radius": 1, "flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         return revolved(CutterType::Bull, k, f);
       }},
      {"taper_ball",
       "tapered ball mill: a ball tip on a cone (rib and blade finishing)",
       {{"tip_radius", "the ball tip's radius, mm (> 0)", true},
        kTaper,
        kFluteLengthOr,
        kFluteDiameter},
       {{"taper_ball", "taper_ball r1 5°",
         R"({"type": "taper_ball", "tip_radius": 1, "taper_deg": 5, "flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         TaperBallShape s;
         s.tipRadius = k["tip_radius"], s.taperDeg = k["taper_deg"];
         s.fluteLength = k["flute_length"], s.fluteDiameter = k["flute_diameter"];
         return cutterOfChain(CutterType::TaperBall, taperBallChain(s, f), f);
       }},
      {"taper_bull",
       "tapered corner-radius mill: a flat bottom, a corner arc and a cone",
       {{"tip_diameter", "where the bottom and the flank, extended, meet, mm (> 0)", true},
        {"corner_radius", "the arc tangent to bottom and flank, mm (>= 0, below the tip's)", true},
        kTaper,
        kFluteLengthOr,
        kFluteDiameter},
       {{"taper_bull", "taper_bull d4 r1 8°",
         R"({"type": "taper_bull", "tip_diameter": 4, "corner_radius": 1, "taper_deg": 8, )"
         R"("flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         TaperBullShape s;
         s.tipDiameter = k["tip_diameter"], s.cornerRadius = k["corner_radius"];
         s.taperDeg = k["taper_deg"];
         s.fluteLength = k["flute_length"], s.fluteDiameter = k["flute_diameter"];
         return cutterOfChain(CutterType::TaperBull, taperBullChain(s, f), f);
       }},
      {"cone",
       "V-bit, chamfer mill, drill point: a cone from a point or a flat tip",
       {{"angle_deg", "the included angle, degrees (0, 180)", true},
        {"tip_diameter", "the flat tip's diameter, mm (0: a point; below diameter)", false},
        {"diameter", "the cylinder's diameter above the cone, mm (> 0)", true},
        {"flute_length", "L, mm (at least the cone's height)", true}},
       {{"cone_vbit", "cone 60° V-bit",
         R"({"type": "cone", "angle_deg": 60, "diameter": 6, "flute_length": 12})"},
        {"cone_chamfer", "cone 90° d1 chamfer",
         R"({"type": "cone", "angle_deg": 90, "tip_diameter": 1, "diameter": 6, )"
         R"("flute_length": 8})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         ConeShape s;
         s.angleDeg = k["angle_deg"], s.tipDiameter = k["tip_diameter"];
         s.diameter = k["diameter"], s.fluteLength = k["flute_length"];
         return cutterOfChain(CutterType::Cone, coneChain(s, f), f);
       }},
      {"barrel",
       "barrel: a side arc of large radius, widest at its equator",
       {{"diameter", "the widest diameter, mm (> 0)", true},
        {"form_radius", "the side arc's radius, mm (> diameter / 2)", true},
        {"tip_radius", "the corner arc to the flat bottom, mm (0: a sharp edge)", false},
        {"equator_height", "the widest point above the tip, mm (default L / 2)", false},
        kFluteLength},
       {{"barrel", "barrel d12 R40 r1",
         R"({"type": "barrel", "diameter": 12, "form_radius": 40, "tip_radius": 1, )"
         R"("flute_length": 12})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         BarrelShape s;
         s.diameter = k["diameter"], s.formRadius = k["form_radius"];
         s.tipRadius = k["tip_radius"], s.fluteLength = k["flute_length"];
         s.equatorHeight = k.given("equator_height") ? k["equator_height"] : s.fluteLength / 2;
         return cutterOfChain(CutterType::Barrel, barrelChain(s, f), f);
       }},
      {"taper_barrel",
       "taper barrel (conical barrel): a ball tip and a side arc of large radius",
       {{"tip_radius", "the ball tip's radius, mm (> 0)", true},
        {"form_radius", "the side arc's radius, mm (> tip_radius)", true},
        {"taper_deg", "the side arc's angle to the axis at the reference, degrees [0, 45]", true},
        {"reference_diameter", "where the side arc makes taper_deg, mm (> 0)", true},
        kFluteLength},
       {{"taper_barrel", "taper_barrel r2 R250 10°",
         R"({"type": "taper_barrel", "tip_radius": 2, "form_radius": 250, "taper_deg": 10, )"
         R"("reference_diameter": 8, "flute_length": 20})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         TaperBarrelShape s;
         s.tipRadius = k["tip_radius"], s.formRadius = k["form_radius"];
         s.taperDeg = k["taper_deg"], s.referenceDiameter = k["reference_diameter"];
         s.fluteLength = k["flute_length"];
         return cutterOfChain(CutterType::TaperBarrel, taperBarrelChain(s, f), f);
       }},
      {"oval",
       "oval: a ball tip and a side arc widest at its diameter",
       {{"diameter", "the widest diameter, mm (> 0)", true},
        {"form_radius", "the side arc's radius, mm (> diameter / 2)", true},
        {"tip_radius", "the ball tip's radius, mm (0 < r < diameter / 2)", true},
        kFluteLength},
       {{"oval", "oval d8 R12 r1.5",
         R"({"type": "oval", "diameter": 8, "form_radius": 12, "tip_radius": 1.5, )"
         R"("flute_length": 10})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         OvalShape s;
         s.diameter = k["diameter"], s.formRadius = k["form_radius"];
         s.tipRadius = k["tip_radius"], s.fluteLength = k["flute_length"];
         return cutterOfChain(CutterType::Oval, ovalChain(s, f), f);
       }},
      {"lens",
       "lens: a tip arc centred on the axis, a corner arc and a cylinder",
       {{"diameter", "the cylinder's diameter, mm (> 0)", true},
        {"form_radius", "the tip arc's radius, mm (> diameter / 2)", true},
        {"corner_radius", "the arc from the tip arc to the cylinder, mm (0: a sharp edge)", false},
        kFluteLength},
       {{"lens", "lens d10 R12 r1",
         R"({"type": "lens", "diameter": 10, "form_radius": 12, "corner_radius": 1, )"
         R"("flute_length": 8})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         LensShape s;
         s.diameter = k["diameter"], s.formRadius = k["form_radius"];
         s.cornerRadius = k["corner_radius"], s.fluteLength = k["flute_length"];
         return cutterOfChain(CutterType::Lens, lensChain(s, f), f);
       }},
      {"profile",
       "any convex profile: segments (lines and arcs) from the tip up",
       {{"segments",
         "[{\"to\": [rho, s]}, {\"to\": [rho, s], \"arc_radius\": R}, ...] from [0, 0], mm", true}},
       {{"profile", "profile",
         R"({"type": "profile", "segments": [{"to": [1, 0]}, )"
         R"({"to": [1.7071067811865475, 0.2928932188134524], "arc_radius": 1}, )"
         R"({"to": [2.5, 1.2]}, {"to": [3, 10]}]})"}},
       [](const CutterKeyValues&, const json& tool, const std::string& f) {
         return cutterOfChain(CutterType::Profile, parseSegments(tool, f), f);
       }},
      {"apt",
       "APT's 7-value CUTTER/d, r, e, f, a, b, h",
       {{"d", "diameter, mm (> 0)", true},
        {"r", "corner radius, mm (>= 0)", true},
        {"e", "the corner centre's radius, mm", true},
        {"f", "the corner centre's height, mm", true},
        {"a", "the bottom line's angle, degrees [0, 90)", true},
        {"b", "the side line's angle to the axis, degrees (-90, 90), a + b < 90", true},
        {"h", "the height, mm (> 0)", true}},
       {{"apt", "APT CUTTER/6,1,2,2.309,30,0,10",
         R"({"type": "apt", "d": 6, "r": 1, "e": 2, "f": 2.3094010767585, "a": 30, "b": 0, )"
         R"("h": 10})"}},
       [](const CutterKeyValues& k, const json&, const std::string& f) {
         AptCutterValues v;
         v.d = k["d"], v.r = k["r"], v.e = k["e"], v.f = k["f"];
         v.a = k["a"], v.b = k["b"], v.h = k["h"];
         return aptCutter(v, f);
       }},
  };
  return table;
}

const CutterShape* findCutterShape(const std::string& type) {
  for (const CutterShape& shape : cutterShapes())
    if (type == shape.type) return &shape;
  return nullptr;
}

std::string cutterTypeList() {
  const std::vector<CutterShape>& table = cutterShapes();
  std::string text;
  for (size_t k = 0; k < table.size(); ++k)
    text += (k == 0 ? "" : k + 1 == table.size() ? " or " : ", ") + std::string(table[k].type);
  return text;
}

Cutter parseCutterShape(const json& tool, const std::set<std::string>& teethKeys,
                        const std::string& f) {
  const std::string type = text(tool, "type", f + ".type");
  const CutterShape* shape = findCutterShape(type);
  if (!shape)
    throw InputError(f + ".type",
                     "unknown cutter type \"" + type + "\", expected " + cutterTypeList());
  std::set<std::string> known = teethKeys;
  known.insert("type");
  for (const CutterKey& key : shape->keys) known.insert(key.name);
  rejectUnknownKeys(tool, known, f);
  CutterKeyValues values;
  for (const CutterKey& key : shape->keys) {
    if (std::string(key.name) == "segments") continue;  // not a number: the builder's
    if (key.required || tool.contains(key.name))
      values.set(key.name, number(tool, key.name, f + "." + key.name));
  }
  return shape->build(values, tool, f);
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
