// From tool path to swept moves: drops rapids, makes one SweptMove per cutting move
// (whatever its axis does) with the cutter of that move, and merges consecutive
// collinear moves with one axis and one cutter (CONVENTIONS.md "Tool pose", "Tools").
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/cutting_model.h"
#include "sweep/pose.h"
#include "sweep/swept_move.h"

namespace scallop {

// An xy window of a map (mm): the lines of its cells lie inside [x0, x1] x [y0, y1]. A
// sweep given a window keeps only the moves whose swept solid may reach it; the others
// cannot change a height there. A scene built per band of a map holds the band's moves
// only (tools/run/tiled_simulation.h: a path whose whole scene does not fit in memory).
struct SweepWindow {
  double x0 = -HUGE_VAL, y0 = -HUGE_VAL, x1 = HUGE_VAL, y1 = HUGE_VAL;
  bool meets(const Box3& box) const {
    return box.max.x >= x0 && box.min.x <= x1 && box.max.y >= y0 && box.min.y <= y1;
  }
};

// Every cutting move becomes one SweptMove whose pose curve is PoseCurve::ofMove (tip
// linear and axis slerp(from.axis, to.axis, t), or the machine's rotary motion), swept
// with cutters[move.tool]. Consecutive collinear moves with the same constant axis and
// cutter are merged: the swept solid of their union is the same set. A turn of 180
// degrees and a tool index beyond `cutters` are InputErrors naming the move.
//
// With the "teeth" cutting model each move also carries its edges (ToothSweep) with the
// spindle angle phi(s) = phi0 + 2 pi s / (flutes fz) of CuttingModel, s the tip's
// distance along the path; its envelope is then the cutter's spindleEnvelope(). A move
// without a feed per tooth (neither its own nor the model's), or whose tip follows a
// machine's curve (TCP off), is an InputError naming the move; an arc's s is its arc
// length. Arcs (Move::arc) are single moves, never merged.
//
// With a `window`, only the entries whose swept solid's box meets it are kept (after
// merging, so those kept are the same moves, bit for bit, as without a window).
std::vector<SweptMove> sweepToolPath(const std::vector<Cutter>& cutters, const ToolPath& path,
                                     const CuttingModel& cutting = {},
                                     const SweepWindow* window = nullptr);

// The same with path.cutters when the path has its own (a multi-tool program), and
// otherwise `cutter` for every move.
std::vector<SweptMove> sweepToolPath(const Cutter& cutter, const ToolPath& path,
                                     const CuttingModel& cutting = {},
                                     const SweepWindow* window = nullptr);

// sweepToolPath of a path handed over in parts, in order (a file read as a stream, a band
// at a time: tools/run/tiled_simulation.h), without the whole path in memory: the same
// entries, bit for bit, as sweepToolPath(cutters, whole path, cutting, window). Each part
// is a ToolPath whose moves continue the previous part's (the same move numbers in the
// messages) and whose Move::arc and Move::rotary index its own arrays; its `cutters` are
// not read (the constructor's are). What the sweep carries from move to move (the
// segment being merged, the spindle's phase) carries across parts.
class ToolPathSweeper {
 public:
  // `cuttingMoves`: room reserved for the entries (the path's cutting moves, or fewer).
  ToolPathSweeper(std::vector<Cutter> cutters, const CuttingModel& cutting,
                  const SweepWindow* window, size_t cuttingMoves);
  ~ToolPathSweeper();
  void add(const ToolPath& part);
  std::vector<SweptMove> finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace scallop
