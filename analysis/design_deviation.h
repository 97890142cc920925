// Design-surface comparison: how far the machined surface (a ZMap of exact swept
// heights) lies above or below the part it should be (a triangle mesh), cell by cell,
// and where and by which moves it was cut too deep (gouges).
//
// The design height of a cell is the mesh's *upper envelope* at the cell centre (a
// top-down ray, MeshIndex::topHeight, height recomputed in double): a 3-axis cutter
// coming from above only ever meets the top layer of a folded or overhanging mesh.
// Cells whose vertical line misses the mesh have no design height and are left out.
//
// Signs: deviation = machined - design. Positive is material left (under-cut),
// negative is material removed that belongs to the part (over-cut); an over-cut
// deeper than the gouge tolerance is a gouge.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/swept_segment.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

struct DeviationSummary {
  int64_t cells = 0;          // cells with a design height
  double min = 0, max = 0;    // machined - design, mm
  double mean = 0, rms = 0;   // mm
  int64_t overcutCells = 0;   // deviation < -tolerance (gouge cells)
  int64_t undercutCells = 0;  // deviation > +tolerance
  double overcutAreaMm2 = 0, undercutAreaMm2 = 0;
};

// One gouge: a 4-connected region of cells deeper than the tolerance below the design.
struct Gouge {
  int64_t cells = 0;
  double areaMm2 = 0;
  double depth = 0;      // design - machined at the deepest cell, mm (> tolerance)
  int64_t i = 0, j = 0;  // the deepest cell
  double x = 0, y = 0;   // its centre, mm
  double designZ = 0, machinedZ = 0;
  std::vector<size_t> moves;  // indices into ToolPath::moves whose sweep makes the
                              // machined height at the region's deepest cells
};

struct DesignComparison {
  GridSpec grid;
  double tolerance = 0;           // gouge tolerance, mm
  std::vector<double> deviation;  // per cell in ZMap order; NaN: no design there, or no
                                  // material (a frame's void cell)
  DeviationSummary summary;
  std::vector<Gouge> gouges;  // deepest first
};

// Deviation, summary and gouge regions (without their moves; see attributeGouges).
// Design heights come from designHeights (analysis/gouge_check.h).
DesignComparison compareWithDesign(const ZMap& machined, const MeshIndex& design,
                                   double gougeTolerance);

// Which cutting moves of a path make given heights. Each move is swept on its own
// (never merged with its neighbours, unlike sweepToolPath) so a height is traced to
// the move, and so to the file line, that made it. Only moves whose reach meets one
// of `areas` (xy boxes, mm) are swept, so a huge path costs memory only near them.
class MoveFinder {
 public:
  MoveFinder(const Cutter& cutter, const ToolPath& path, const std::vector<Box3>& areas);
  ~MoveFinder();
  MoveFinder(const MoveFinder&) = delete;
  MoveFinder& operator=(const MoveFinder&) = delete;

  // Indices of the moves whose swept solid's exact lowest point on the vertical line
  // through (x, y) is at most z + tolerance, ascending. Thread-safe.
  std::vector<size_t> movesAt(double x, double y, double z, double tolerance) const;
  // The lowest exact height of one move's sweep at (x, y); HUGE_VAL when it misses.
  double moveHeight(size_t move, double x, double y) const;

  size_t sweptMoves() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Fills Gouge::moves from the path that made `machined`: the moves within 1e-7 mm of
// the machined height at each region's deepest cells (at most `cellsPerGouge` of
// them, deepest first).
void attributeGouges(DesignComparison& comparison, const ZMap& machined, const Cutter& cutter,
                     const ToolPath& path, int cellsPerGouge = 16);

}  // namespace scallop
