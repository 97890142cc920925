// Interval comparison: the path-interval procedures of the seeds next to the simulated
// truth for one cutter, posture and scallop height, and its JSON document. One owner
// for `scallop interval` (tools/cli/interval_command.cpp) and the Python module's
// interval() (tools/python), so both give the same document.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "analysis/feed_mark_formula.h"
#include "analysis/simulated_interval.h"
#include "sweep/cutter.h"

namespace scallop {

// One procedure of analysis/path_interval.h, and what its L/2 really leaves.
struct ProcedureComparison {
  std::string name;    // the seeds' kProcedures names, "exact", "effective_radius"
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
  // Along the feed, with a feed per tooth (analysis/feed_mark_formula.h): the cutter's
  // teeth (flutes, runout) and the feed marks' closed form.
  double feedPerToothMm = 0;  // 0: not asked
  FeedMarkPrediction feedMarks;
};

// Runs every procedure for `h` and simulates each L/2 on `pass`: the seeds' (kProcedures
// order), then "exact" (analysis/pass_section.h) and "effective_radius"
// (analysis/contact_curvature.h), which take any cutter, lead and tilt. The seed 000
// bull procedures model inclination along the feed only, so with a tilt they are
// reported as not applicable; none of the seeds' describes a flat end mill or a
// profile cutter.
IntervalComparison compareIntervals(const SimulatedPass& pass, double scallopMm);

// The `interval --json` document (lengths in mm, angles in degrees).
nlohmann::json toJson(const IntervalComparison& comparison);
nlohmann::json toolJson(const Cutter& cutter);

// What an interval comparison is asked for, as given (unchecked).
struct IntervalRequest {
  std::string tool;  // "ball", "bull" or "flat"
  double radiusMm = 0, cornerRadiusMm = 0;
  bool cornerGiven = false;  // whether a corner radius was given at all
  double leadDeg = 0, tiltDeg = 0, scallopMm = 0;
  // The feed marks beside the path interval, when a feed per tooth (> 0) is given.
  bool feedPerToothGiven = false;
  double feedPerToothMm = 0;
  int flutes = 2;
  double runoutMm = 0;
};

// The names that errors give the request's fields: the CLI's options by default, the
// Python keywords (corner_radius, ...) in the module.
struct IntervalFieldNames {
  const char* tool = "--tool";
  const char* radius = "--radius";
  const char* cornerRadius = "--corner-radius";
  const char* lead = "--lead";
  const char* tilt = "--tilt";
  const char* scallop = "--scallop";
  const char* feedPerTooth = "--feed-per-tooth";
  const char* flutes = "--flutes";
  const char* runout = "--runout";
};

// Checks every field (InputError naming it and what was expected: a bull cutter
// without a corner radius, angles with |angle| >= 90, h <= 0, an h the cutter cannot
// leave, fz < 0, flutes outside 1..16, runout outside [0, R / 10]) and runs
// compareIntervals, and with fz > 0 predictFeedMarks.
IntervalComparison compareIntervals(const IntervalRequest& request,
                                    const IntervalFieldNames& names = {});

// Checks the options of a cutter with messages that name them (InputError, exit 1).
Cutter cutterFromOptions(const std::string& tool, double radius, double cornerRadius,
                         bool cornerGiven, const IntervalFieldNames& names = {});
void checkAngleOption(const char* option, double deg);

}  // namespace scallop
