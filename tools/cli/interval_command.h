// `scallop interval`: the path-interval procedures of the seeds next to the simulated
// truth for one cutter, posture and scallop height; and the comparison it prints,
// shared with `scallop validate`.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "analysis/simulated_interval.h"
#include "sweep/cutter.h"

namespace scallop {

// One procedure of analysis/path_interval.h, and what its L/2 really leaves.
struct ProcedureComparison {
  std::string name;    // "computational", "sekine", "redonnet", "bedi", "ball"
  std::string source;  // seed and equation numbers
  bool applicable = false;
  std::string reason;         // why not applicable; empty otherwise
  double halfIntervalMm = 0;  // the procedure's L/2
  SimulatedCusp cusp;         // two passes 2 L/2 apart, simulated
};

struct IntervalComparison {
  Cutter cutter;
  double leadDeg = 0, tiltDeg = 0;
  double scallopMm = 0;  // the requested h
  SideIntervals exact;   // the simulated exact L/2 (both sides)
  std::vector<ProcedureComparison> procedures;
};

// Runs every procedure for `h` and simulates each L/2 on `pass`. The seed 000 bull
// procedures model inclination along the feed only, so with a tilt they are reported
// as not applicable; none of them describes a flat end mill.
IntervalComparison compareIntervals(const SimulatedPass& pass, double scallopMm);

// The `interval --json` document (lengths in mm, angles in degrees).
nlohmann::json toJson(const IntervalComparison& comparison);
nlohmann::json toolJson(const Cutter& cutter);

// Checks the options of a cutter, posture and h with messages that name the option
// (InputError, exit 1). `cornerGiven` says whether --corner-radius was given.
Cutter cutterFromOptions(const std::string& tool, double radius, double cornerRadius,
                         bool cornerGiven);
void checkAngleOption(const char* option, double deg);

}  // namespace scallop
