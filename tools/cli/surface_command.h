// `scallop surface`: options and printing; tools/run/surface_run.h writes the surface.
#pragma once

#include <string>

#include "tools/run/surface_run.h"

namespace scallop {

struct SurfaceArgs {
  SurfaceSettings settings;
  bool json = false;  // print the summary as JSON on stdout
};

// Returns the exit status; throws InputError for bad input.
int runSurface(SurfaceArgs args);

}  // namespace scallop
