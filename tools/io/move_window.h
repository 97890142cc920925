// Keeping, as a tool-path file is read, only the moves that can reach the grid: a
// small window of a large program holds and sweeps its own moves, not the program's.
//
// A move is kept when a conservative bound of its swept solid meets the grid's cell
// lines seen from above: the box of its tip's path (a linear tip's two ends, an arc's
// whole circle) grown by the largest cutter's radius plus its flute length times the
// axis's largest lean from the vertical (its two ends': the lean of a slerp or of a
// table's linear tilt never exceeds them; 1 for a machine's rotary move), a rounding
// margin more (sweep/tool_path_sweep.h segmentReach's). A rapid is kept when the bound
// meets the grid or the stock (the crash check reads it). Moves the sweep may merge
// (constant-axis straight cutting moves continuing one another along one line, as
// tool_path_sweep.cpp's `continues`, with looser tolerances so that a group is never
// smaller) are kept or left out as one group, so the sweep makes the same segments, bit
// for bit; a group left out is kept after all when the next group could continue the
// last group kept (the sweep would otherwise merge across the gap). Kept too, so that
// the checks after reading still see them: a move beyond 1 km, a cutting move without
// a feed per tooth under the teeth model, a machine move with TCP off.
//
// The modal state advances over every move as before (the readers make every move);
// with the teeth model the spindle's phase is carried across the moves left out:
// ToolPath::phaseMarks holds the phase, computed as the sweep computes it over every
// move, at each kept move whose predecessor was left out.
#pragma once

#include <cstdint>
#include <vector>

#include "base/vec3.h"
#include "sweep/cutting_model.h"
#include "sweep/pose.h"

namespace scallop {

struct ReadWindow {
  // The grid's cell lines seen from above (their centres' extent), mm.
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  // The stock's box: rapids whose bound meets its xy are kept for the crash check.
  Box3 stock;
  // The largest radius and flute length of every cutter the program may cut with (with
  // teeth, their spindle envelopes', the flute length grown by the teeth's axial reach).
  double radius = 0, fluteLength = 0;
  // The teeth model's inputs of the spindle's phase: the job's cutting model, and the
  // flute count when one tool cuts every move (0: each move's own tool, path.cutters).
  CuttingModel cutting;
  int oneToolFlutes = 0;
};

// The filter a reader's ToolPathFile runs its moves through (ToolPathFile::addMove).
class MoveWindowFilter {
 public:
  explicit MoveWindowFilter(const ReadWindow& window);

  // Judges the last move of `path` (complete: called before the next move is added),
  // and leaves out of path.moves and `lines` the moves whose fate is settled and that
  // cannot reach the grid.
  void judgeLast(ToolPath& path, std::vector<int64_t>& lines);
  // After the last move: settles and compacts the rest (at least one move stays).
  void finish(ToolPath& path, std::vector<int64_t>& lines);

  size_t movesRead() const { return read_; }
  // Per tool index (Move::tool), of every cutting move read: how many, the first and the
  // last line (report.json path_file.tools describes the program, not the window).
  struct ToolMoves {
    int64_t count = 0, firstLine = 0, lastLine = 0;
  };
  const std::vector<ToolMoves>& toolMoves() const { return toolMoves_; }
  size_t movesLeftOut() const { return leftOut_; }

 private:
  struct Judged {
    bool cutting = false, keep = false;
    double phase = 0;  // the spindle's, at the move's start (teeth)
  };
  // A run of moves the sweep may merge: [first, end) in pending_, its merged ends.
  struct Group {
    bool open = false, mergeable = false, meets = false;
    size_t first = 0, end = 0;
    Vec3 from, to, axis;
  };

  bool meets(const ToolPath& path, const Move& mv, bool& forced) const;
  double radiansPerMm(const ToolPath& path, const Move& mv) const;
  bool continues(const Group& g, const Move& mv) const;
  void decide(Group& g, bool keep);
  void compact(ToolPath& path, std::vector<int64_t>& lines, size_t finalEnd);

  ReadWindow w_;
  bool teeth_ = false;
  double phase_ = 0;
  std::vector<Judged> pending_;  // one per move of path.moves from base_ on
  size_t base_ = 0;
  Group open_, held_;  // held_: the last group, left out, until the next one starts
  bool lastKept_ = false, lastKeptMergeable_ = false;
  Vec3 lastKeptTo_, lastKeptAxis_;
  bool previousLeftOut_ = false;  // the last final move was left out
  size_t read_ = 0, leftOut_ = 0, kept_ = 0;
  std::vector<ToolMoves> toolMoves_;
};

}  // namespace scallop
