// A job of `n` identical 0.1 mm moves of a ball R1 at (1, 1, -0.2) over a 20 x 20 mm
// stock on a grid of `spacingMm`: the smallest path whose size the memory tests choose.
#pragma once

#include <string>

#include "tools/io/job.h"

namespace scallop::test {

inline Job shortMovesJob(size_t n, double spacingMm, const std::string& file) {
  Job job = parseJob(R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -1], "max": [20, 20, 0]}, "grid": {"spacing": )" +
                         std::to_string(spacingMm) + R"(},
    "path": {"raster": {"direction": "x", "step_over": 30, "depth": 0.2}}})",
                     file);
  Move m;
  m.from = {{1, 1, -0.2}, {0, 0, 1}};
  m.to = {{1.1, 1, -0.2}, {0, 0, 1}};
  job.path.moves.assign(n, m);
  return job;
}

}  // namespace scallop::test
