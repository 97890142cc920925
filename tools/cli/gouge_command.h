// `scallop gouge`: seed 004's peripheral-milling strategy on an STL surface, and the
// exact check of every posture it accepts (analysis/peripheral_strategy.h,
// analysis/gouge_check.h).
#pragma once

#include <string>

#include "analysis/peripheral_strategy.h"

namespace scallop {

struct GougeArgs {
  std::string surface;  // STL file
  double radius = 0;    // R, mm
  double length = 0;    // flute length L, mm
  StrategyOptions strategy;
  std::string feed = "x";
  std::string inclinationAxis = "normal";
  std::string normals = "up";   // up | file
  double mapTolerance = 1e-2;   // mm
  double gridSpacing = 0;       // mm; <= 0: longest side / 300
  bool noMap = false;
  std::string posturesCsv;  // optional
  std::string outDir;       // optional
  bool json = false;
  int threads = 0;
};

// Returns the exit status; throws InputError for bad input.
int runGouge(GougeArgs args);

}  // namespace scallop
