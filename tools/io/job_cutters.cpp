#include "tools/io/job_cutters.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "base/input_error.h"
#include "tools/io/job_cutter_shapes.h"
#include "tools/io/job_fields.h"

namespace scallop {

using nlohmann::json;
using namespace jobfield;

namespace {

// A JSON number at `field` (an array entry), or an InputError saying what was expected.
double arrayNumber(const json& v, const std::string& field, const char* expected) {
  if (!v.is_number())
    throw InputError(field, std::string("expected ") + expected + ", got " + v.dump());
  return v.get<double>();
}

// A [from_mm, to_mm] pair at `field`.
EdgeSpan spanPair(const json& v, const std::string& field) {
  if (!v.is_array() || v.size() != 2)
    throw InputError(field,
                     "expected a pair [from_mm, to_mm] (arc length along the profile "
                     "from the axis), got " +
                         v.dump());
  return {arrayNumber(v[0], field + "[0]", "an arc length in mm"),
          arrayNumber(v[1], field + "[1]", "an arc length in mm")};
}

// "edge_span": [from_mm, to_mm] (every tooth) or "tooth_edge_spans": [[from_mm, to_mm],
// ...] (one per flute), not both; stored one per flute (tooth_geometry.h checks them).
void parseEdgeSpans(const json& tool, const std::string& f, Cutter& cutter) {
  CutterTeeth& teeth = cutter.teeth;
  const bool one = tool.contains("edge_span"), each = tool.contains("tooth_edge_spans");
  if (one && each)
    throw InputError(f + ".tooth_edge_spans",
                     "give edge_span (every tooth) or tooth_edge_spans (one per flute), not both");
  if (one) {
    const std::string field = f + ".edge_span";
    const EdgeSpan span = spanPair(tool.at("edge_span"), field);
    checkEdgeSpans({span}, teeth.flutes, cutter.edgeLength(), field, false);
    teeth.editEdgeSpans().assign(size_t(teeth.flutes), span);
  } else if (each) {
    const std::string field = f + ".tooth_edge_spans";
    const json& a = tool.at("tooth_edge_spans");
    if (!a.is_array())
      throw InputError(field, "expected an array of [from_mm, to_mm] pairs, one per flute");
    for (size_t k = 0; k < a.size(); ++k)
      teeth.editEdgeSpans().push_back(spanPair(a[k], field + "[" + std::to_string(k) + "]"));
    checkEdgeSpans(teeth.edgeSpans(), teeth.flutes, cutter.edgeLength(), field, true);
  }
}

// "rake_deg": [axial_deg, radial_deg] (every tooth) or "tooth_rakes_deg": [[axial_deg,
// radial_deg], ...] (one per flute), not both; stored one per flute. Read after the
// spans: a rake face passes through its span's start (Cutter::checkRakes).
ToothRake rakePair(const json& v, const std::string& field) {
  if (!v.is_array() || v.size() != 2)
    throw InputError(
        field, "expected a pair [axial_deg, radial_deg] (the rake face's angles), got " + v.dump());
  return {arrayNumber(v[0], field + "[0]", "an axial rake in degrees"),
          arrayNumber(v[1], field + "[1]", "a radial rake in degrees")};
}

void parseRakes(const json& tool, const std::string& f, Cutter& cutter) {
  CutterTeeth& teeth = cutter.teeth;
  const bool one = tool.contains("rake_deg"), each = tool.contains("tooth_rakes_deg");
  if (one && each)
    throw InputError(f + ".tooth_rakes_deg",
                     "give rake_deg (every tooth) or tooth_rakes_deg (one per flute), not both");
  std::string field;
  if (one) {
    field = f + ".rake_deg";
    const ToothRake rake = rakePair(tool.at("rake_deg"), field);
    checkToothRakes({rake}, teeth.flutes, field, false);
    teeth.editToothRakes().assign(size_t(teeth.flutes), rake);
  } else if (each) {
    field = f + ".tooth_rakes_deg";
    const json& a = tool.at("tooth_rakes_deg");
    if (!a.is_array())
      throw InputError(field, "expected an array of [axial_deg, radial_deg] pairs, one per flute");
    for (size_t k = 0; k < a.size(); ++k)
      teeth.editToothRakes().push_back(rakePair(a[k], field + "[" + std::to_string(k) + "]"));
    checkToothRakes(teeth.toothRakes(), teeth.flutes, field, true);
  }
  if (one || each) cutter.checkRakes(field);
}

// "tooth_angles_deg": [deg, ...] and "tooth_offsets": [[radial_mm, axial_mm], ...], one
// entry per flute (tooth_geometry.h checks the values).
void parseToothGeometry(const json& tool, const std::string& f, Cutter& cutter) {
  CutterTeeth& teeth = cutter.teeth;
  if (tool.contains("tooth_angles_deg")) {
    const std::string field = f + ".tooth_angles_deg";
    const json& a = tool.at("tooth_angles_deg");
    if (!a.is_array())
      throw InputError(field, "expected an array of body angles in degrees, one per flute");
    for (size_t k = 0; k < a.size(); ++k)
      teeth.editToothAnglesDeg().push_back(
          arrayNumber(a[k], field + "[" + std::to_string(k) + "]", "a body angle in degrees"));
  }
  if (tool.contains("tooth_offsets")) {
    const std::string field = f + ".tooth_offsets";
    const json& a = tool.at("tooth_offsets");
    const char* pair = "a pair [radial_mm, axial_mm]";
    if (!a.is_array())
      throw InputError(field, std::string("expected an array of ") + pair + " per flute");
    for (size_t k = 0; k < a.size(); ++k) {
      const std::string entry = field + "[" + std::to_string(k) + "]";
      if (!a[k].is_array() || a[k].size() != 2)
        throw InputError(entry, std::string("expected ") + pair + ", got " + a[k].dump());
      teeth.editToothOffsets().push_back(
          {arrayNumber(a[k][0], entry + "[0]", "a radial offset in mm"),
           arrayNumber(a[k][1], entry + "[1]", "an axial offset in mm")});
    }
  }
  // A general cutter's flat bottom is its profile's (its cornerRadius is 0).
  checkToothGeometry(teeth.toothAnglesDeg(), teeth.toothOffsets(), teeth.flutes, cutter.radius,
                     cutter.general() ? cutter.profile->bottomRadius() : cutter.bottomRadius(), f);
  parseEdgeSpans(tool, f, cutter);
  parseRakes(tool, f, cutter);
}

}  // namespace

Cutter parseCutter(const json& tool, const std::string& f) {
  static const std::set<std::string> teethKeys = {
      "flutes",        "helix_deg", "runout_mm",        "runout_phase_deg", "tooth_angles_deg",
      "tooth_offsets", "edge_span", "tooth_edge_spans", "rake_deg",         "tooth_rakes_deg"};
  Cutter cutter = parseCutterShape(tool, teethKeys, f);
  // The teeth: the types checked here, the ranges in CutterTeeth::make (one place).
  const CutterTeeth defaults;
  const int64_t flutes = wholeNumber(tool, "flutes", f + ".flutes", defaults.flutes, "teeth");
  const double helix = number(tool, "helix_deg", f + ".helix_deg", &defaults.helixDeg);
  const double runout = number(tool, "runout_mm", f + ".runout_mm", &defaults.runout);
  const double phase =
      number(tool, "runout_phase_deg", f + ".runout_phase_deg", &defaults.runoutPhaseDeg);
  cutter.teeth = CutterTeeth::make(int(flutes), helix, runout, phase, cutter.radius, f);
  parseToothGeometry(tool, f, cutter);
  return cutter;
}

std::map<int64_t, Cutter> parseTools(const json& tools) {
  std::map<int64_t, Cutter> out;
  for (auto it = tools.begin(); it != tools.end(); ++it) {
    const std::string& key = it.key();
    const std::string f = "tools." + key;
    if (key.empty() || key.size() > 9 || key.find_first_not_of("0123456789") != std::string::npos ||
        key[0] == '0')
      throw InputError(f, "expected a tool number (the G-code T word: 1, 2, ...) as the key");
    if (!it.value().is_object()) throw InputError(f, "expected a cutter object");
    out[std::stoll(key)] = parseCutter(it.value(), f);
  }
  if (out.empty()) throw InputError("tools", "expected at least one tool");
  return out;
}

bool parseSpindle(const json& doc) {
  if (!doc.contains("spindle")) return false;
  const json& v = doc.at("spindle");
  if (v == "cw") return false;
  if (v == "ccw") return true;
  throw InputError("spindle",
                   "expected \"cw\" (clockwise seen from the shank, M3) or \"ccw\" "
                   "(counter-clockwise, M4), got " +
                       v.dump());
}

CuttingModel parseCuttingModel(const json& c) {
  rejectUnknownKeys(c, {"model", "feed_per_tooth", "phase_deg"}, "cutting");
  CuttingModel model;
  if (c.contains("model")) {
    const std::string kind = text(c, "model", "cutting.model");
    if (kind == "teeth")
      model.kind = CuttingModelKind::Teeth;
    else if (kind != "envelope")
      throw InputError("cutting.model",
                       "expected \"envelope\" (the swept solid of revolution) or "
                       "\"teeth\" (the cutting edges), got \"" +
                           kind + "\"");
  }
  if (c.contains("feed_per_tooth")) {
    model.feedPerTooth = number(c, "feed_per_tooth", "cutting.feed_per_tooth");
    if (!(model.feedPerTooth > 0))
      throw InputError("cutting.feed_per_tooth",
                       "must be a feed per tooth > 0 mm, got " + c.at("feed_per_tooth").dump());
  }
  model.phaseDeg = number(c, "phase_deg", "cutting.phase_deg", &model.phaseDeg);
  return model;
}

const char* toString(CuttingModelKind kind) {
  return kind == CuttingModelKind::Teeth ? "teeth" : "envelope";
}

json cutterToJson(const Cutter& c) {
  json j = {{"type", toString(c.type)},        {"radius", c.radius},
            {"corner_radius", c.cornerRadius}, {"flute_length", c.fluteLength},
            {"flutes", c.teeth.flutes},        {"helix_deg", c.teeth.helixDeg},
            {"runout_mm", c.teeth.runout},     {"runout_phase_deg", c.teeth.runoutPhaseDeg}};
  if (!c.teeth.toothAnglesDeg().empty()) j["tooth_angles_deg"] = c.teeth.toothAnglesDeg();
  if (!c.teeth.toothOffsets().empty()) {
    json offsets = json::array();
    for (const ToothOffset& o : c.teeth.toothOffsets()) offsets.push_back({o.radial, o.axial});
    j["tooth_offsets"] = offsets;
  }
  const std::vector<EdgeSpan>& spans = c.teeth.edgeSpans();
  if (!spans.empty()) {
    if (std::all_of(spans.begin(), spans.end(), [&](const EdgeSpan& e) { return e == spans[0]; })) {
      j["edge_span"] = {spans[0].from, spans[0].to};
    } else {
      json each = json::array();
      for (const EdgeSpan& e : spans) each.push_back({e.from, e.to});
      j["tooth_edge_spans"] = each;
    }
  }
  const std::vector<ToothRake>& rakes = c.teeth.toothRakes();
  if (!rakes.empty()) {
    if (std::all_of(rakes.begin(), rakes.end(),
                    [&](const ToothRake& r) { return r == rakes[0]; })) {
      j["rake_deg"] = {rakes[0].axialDeg, rakes[0].radialDeg};
    } else {
      json each = json::array();
      for (const ToothRake& r : rakes) each.push_back({r.axialDeg, r.radialDeg});
      j["tooth_rakes_deg"] = each;
    }
  }
  // A general cutter's solid is its profile: echoed, so a report says what was swept.
  if (c.general()) j["segments"] = profileSegmentsToJson(*c.profile);
  return j;
}

json cuttingModelToJson(const CuttingModel& cutting) {
  json j = {{"model", toString(cutting.kind)}};
  if (cutting.feedPerTooth > 0) j["feed_per_tooth"] = cutting.feedPerTooth;
  j["phase_deg"] = cutting.phaseDeg;
  return j;
}

}  // namespace scallop
