// `scallop surface`: writes a faceted test surface (analysis/analytic_surfaces.h) as STL,
// the stand-ins for seed 004's unpublished test models.
#pragma once

#include <string>

#include "analysis/analytic_surfaces.h"

namespace scallop {

struct SurfaceArgs {
  SurfaceSpec spec;
  std::string shape = "dome";
  std::string output;  // FILE.stl
  bool ascii = false;  // ASCII STL instead of binary
  bool json = false;   // print the summary as JSON on stdout
};

// Returns the exit status; throws InputError for bad input.
int runSurface(SurfaceArgs args);

}  // namespace scallop
