// What `scallop cutter` shows: a cutter read from a cutter object (inline JSON or a
// file, or a job file's "tool"), described as its profile chain (type, largest radius,
// flute length, each segment) in JSON and as a table for people, and drawn as an SVG
// (tools/render/cutter_svg.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "sweep/cutter.h"

namespace scallop {

// `argument` is a cutter object as JSON text ("{"type": ...}") or the path of a file
// holding one or a job with "tool". InputError naming the file / field otherwise.
Cutter cutterFromArgument(const std::string& argument);

// cutterToJson's echo plus, for ball, flat and bull too, the profile's "segments",
// "max_radius" and "flute_length" (mm).
nlohmann::json cutterDocument(const Cutter& cutter);

// The same for people: one line per segment.
std::string cutterTable(const Cutter& cutter);

// The cutter-shape table (tools/io/job_cutter_shapes.h) for `scallop cutter --list`:
// each type with its summary, its keys (meaning, unit, range; required or not) and its
// example pictures, as JSON and as text for people.
nlohmann::json cutterShapesDocument();
std::string cutterShapesText();
// One line per picture, "file<TAB>title<TAB>tool", for scripts/cutter-images.sh.
std::string cutterPictureLines();

// Writes the profile picture to `path` atomically.
void writeCutterSvg(const Cutter& cutter, const std::string& title, const std::string& path);

}  // namespace scallop
