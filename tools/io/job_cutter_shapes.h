// The cutter-shape table: one entry a `tool.type` (CONVENTIONS.md "Cutters", "Cutter
// shapes"), with its job keys (units and ranges in words), the builder that turns them
// into a Cutter, a help line and the pictures of docs/cutters.md. Read by the job parser
// (tools/io/job_cutters.h), `scallop cutter --list` and `simulate --help`, report.json's
// cutter description and scripts/cutter-images.sh (through `scallop cutter --pictures`).
// Each key is read here once and its range checked once, by the builder in sweep/
// (sweep/cutter.h, sweep/cutter_shapes.h, sweep/apt_cutter.h) where its meaning lives.
// Adding a shape: its builder in sweep/, then one entry in job_cutter_shapes.cpp.
#pragma once

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>
#include <vector>

#include "sweep/cutter.h"

namespace scallop {

struct CutterKey {
  const char* name;     // the job key: "tip_radius"
  const char* meaning;  // with its unit and range: "radius of the ball tip, mm (> 0)"
  bool required;
};

// An example of the shape, drawn by scripts/cutter-images.sh as
// docs/images/cutters/<file>.svg.
struct CutterPicture {
  const char* file;
  const char* title;
  const char* tool;  // the cutter object, JSON
};

// The numbers read for a shape's keys: an optional key left out reads 0.
class CutterKeyValues {
 public:
  double operator[](const std::string& key) const;
  bool given(const std::string& key) const { return values_.count(key) > 0; }
  void set(const std::string& key, double value) { values_[key] = value; }

 private:
  std::map<std::string, double> values_;
};

struct CutterShape {
  const char* type;
  const char* summary;  // one line for --help and the docs
  std::vector<CutterKey> keys;
  std::vector<CutterPicture> pictures;
  // The cutter of `keys` (and, for keys that are not numbers, of `tool` itself); every
  // error is an InputError naming `field`.key and the range expected.
  Cutter (*build)(const CutterKeyValues& keys, const nlohmann::json& tool,
                  const std::string& field);
};

// The table, in the order the docs list the types.
const std::vector<CutterShape>& cutterShapes();
// The entry of `type`, or null.
const CutterShape* findCutterShape(const std::string& type);
// "ball, flat, bull, ... or apt": the types, for messages and --help.
std::string cutterTypeList();

// The shape keys of `tool` read at field path `field` ("tool", "tools.2") and built;
// the teeth keys are the caller's. Unknown keys are an error naming `field`.key;
// `teethKeys` are accepted.
Cutter parseCutterShape(const nlohmann::json& tool, const std::set<std::string>& teethKeys,
                        const std::string& field);

// [{"from": [rho, s], "to": [rho, s], "arc_radius": R, "centre": [rho, s]}, ...] (arc
// keys only for arcs): a profile's chain from the tip up, mm.
nlohmann::json profileSegmentsToJson(const CutterProfile& profile);

}  // namespace scallop
