// SweptScene: the culling scene over the swept solids of a tool path, used to find, for
// each vertical line, the few swept segments whose exact height can be the lowest.
//
// Culling, not approximation: every segment's footprint is cut into xy tiles, and each
// tile gets a box that starts at a *proven* lower bound of the segment's heights over
// the tile (from supporting planes of the convex swept solid). A 2-D grid of buckets
// lists every tile over each bucket in ascending order of its bound there (tile_grid.h).
// A cell reads its bucket's list in that order, evaluates each segment whose planes can
// still go below the lowest height found so far, and stops at the first bound at or above
// it, as an upward ray that each hit shortens would (an Embree BVH of the tiles' boxes
// did the same; the grid, built for the region queries anyway, gives the same heights
// with no hierarchy to build: docs/performance-history.md, B9). Heights themselves are
// always computed in double by SweptMove::lowestPoint. Squares of cells gather their
// candidates from the same grid.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sweep/swept_move.h"
#include "sweep/tip_plane_bound.h"

namespace scallop {

struct SceneOptions {
  double tileSize = 0;  // xy tile side, mm; <= 0 picks cutter radius / 8
  double stockTop = 0;  // heights above this never matter (the ray stops there), mm
  // Largest half side of a square region that gatherCandidates() will be asked about,
  // mm: the tile grid (tile_grid.h) is built for it.
  double regionHalfSize = 0;
  // The knot spacing (mm) given to every turning move (SweptMove::setContactKnotSpacing;
  // 0: none); negative leaves the moves' own.
  double contactKnotSpacing = -1;
  // The grid's cells per cutting move of the program that reaches them
  // (programCellsPerMove, raycast/simulation.h; HUGE_VAL: unknown). Below
  // kCellsPerMoveForTiles every move is one culling tile (cullingTileSide).
  double cellsPerMove = HUGE_VAL;
};

// Programs with fewer cells than this per move get one culling tile a move. A tile costs
// the build 5 exact evaluations and its place in the tile grid (with an Embree hierarchy
// it was ~1 KB in all); finer tiles pay back only through the cells they cull for, ~4 exact
// evaluations a cell shared by every move over it. Measured on B9 (callgrind, 4 mm, 6
// cells a move): one tile a move instead of ~19 builds in 133 instead of 633 million
// instructions and casts in 75 instead of 71, the same heights; B3 and B4 (4 300 and
// 490 cells a move full size, ~460 and 101 at the performance guard's areas) keep theirs.
constexpr double kCellsPerMoveForTiles = 64;

// The side (mm) of the culling tiles of a segment whose xy box has the given area
// (mm^2): SceneOptions::tileSize if set; else, in a program of fewer than
// kCellsPerMoveForTiles cells a move, HUGE_VAL (one tile); else max(R / 8, sqrt(area /
// N)) with N = 16 tiles for moves shorter than the cutter radius R and 64 otherwise.
// The memory estimate (estimateSceneBytes, raycast/simulation.h) uses the same rule.
double cullingTileSide(double cutterRadius, double moveLength, double boxArea,
                       const SceneOptions& options);

struct SceneStats {
  size_t segments = 0;          // swept moves (one primitive per cutting move)
  size_t tiles = 0;             // culling tiles
  size_t boundEvaluations = 0;  // exact evaluations spent on building the bounds
  double buildSeconds = 0;
  // The scene's own accounting of what it holds once built, bytes: the moves (the
  // SweptMove objects and what they own, SweptMove::bytesPerMove), the culling tiles
  // and the tile grid.
  size_t moveBytes = 0, tileBytes = 0, gridBytes = 0;
  size_t bytes() const { return moveBytes + tileBytes + gridBytes; }
};

class SweptScene {
 public:
  SweptScene(std::vector<SweptMove> segments, const SceneOptions& options);
  ~SweptScene();
  SweptScene(const SweptScene&) = delete;
  SweptScene& operator=(const SweptScene&) = delete;

  // Scratch for one thread's consecutive queries: memos of plane sections, direct-mapped
  // by (segment, y). Cells of a row share the section of every move along X, and a
  // block of cells visits a few rows in turn. Results do not depend on it, only speed.
  // It also keeps, for tightenCandidates, where the last region's turning candidates
  // touched its centre line (segment, t): the next region's Newton starts there.
  struct QueryCache {
    static constexpr size_t kSlots = 512;
    SectionMemo memo[kSlots];
    SectionMemo* memoFor(uint32_t segment, double y);
    std::vector<std::pair<uint32_t, double>> contacts, nextContacts;
  };

  // The lowest height at (x, y) over all segments, or `ceiling` if none is lower.
  // `evaluations` is incremented by the number of exact evaluations made.
  // `winner`, if given, receives the segment of the returned height (UINT32_MAX if
  // the ceiling was not beaten). If it names a segment on entry (a guess, such as a
  // neighbour's winner), that one is evaluated first: its height prunes the others
  // from the start. The height returned does not depend on the guess.
  double lowestHeight(double x, double y, double ceiling, uint64_t& evaluations,
                      QueryCache* cache = nullptr, uint32_t* winner = nullptr) const;

  // --- Region queries: one candidate search for a whole square of cells --------------
  // A segment that may be lowest somewhere in a region, with one extra lower-bound plane
  // z >= a + b x + c y of its own (none until tightenCandidates) and, for a turning
  // move, its tip-plane bound over the region (tip_plane_bound.h).
  struct Candidate {
    uint32_t tile;
    uint32_t segment;
    bool teeth = false;  // the move has cutting edges (SweptMove::teeth())
    double a = -HUGE_VAL, b = 0, c = 0;
    TipPlaneBound tip;
  };
  // Every segment that can be lower than `ceiling` somewhere in [x0, x1] x [y0, y1]
  // (one candidate per segment, in segment order). The region's half side must not
  // exceed SceneOptions::regionHalfSize.
  void gatherCandidates(double x0, double y0, double x1, double y1, double ceiling,
                        std::vector<Candidate>& candidates) const;
  // Gives each candidate the supporting plane of its swept solid below (x, y) (one
  // exact evaluation each): near (x, y) it is far tighter than the tile planes. A
  // turning move's contact is located from where it was at the last region's centre
  // (`cache`), one region away: B3 1.9 % fewer instructions and 2.5 % fewer evaluations
  // than from the middle of the move. Any contact gives a valid plane (a support plane of
  // the whole solid), so the start changes only how well the planes prune.
  void tightenCandidates(std::vector<Candidate>& candidates, double x, double y,
                         uint64_t& evaluations, QueryCache* cache = nullptr) const;
  // The candidates ordered for a block of cells [x0, x1] x [y0, y1] inside the gathered
  // region: ascending lower bounds over the block (the tighter of each candidate's own
  // plane and its tile's planes, at the block's corners). A cell in the block only
  // needs the candidates whose block bound is below its best height so far.
  struct BlockEntry {
    double bound;
    uint32_t candidate;  // index into the candidates
  };
  // `zTop`, if finite, bounds every height the block's cells will end with: candidates
  // proven above it over the whole block (by their bound, or a turning move's ray
  // clearance for the block's disc of lines) are left out.
  void orderForBlock(const std::vector<Candidate>& candidates, double x0, double y0, double x1,
                     double y1, std::vector<BlockEntry>& order, double zTop = HUGE_VAL) const;
  // The lowest height at (x, y) among the candidates, or `ceiling`: the same value
  // lowestHeight() returns for any (x, y) inside the gathered region. `block` is the
  // order for a block that contains (x, y). `hint`, if given, names a candidate (index)
  // to evaluate first, typically the previous cell's winner: its height, found first,
  // prunes the others by their bounds; on return it holds the index of the winner
  // (UINT32_MAX if the ceiling was not beaten). The height does not depend on the hint
  // or the block, only the number of evaluations and bound tests does.
  double lowestHeightAmong(const std::vector<Candidate>& candidates,
                           const std::vector<BlockEntry>& block, double x, double y, double ceiling,
                           uint64_t& evaluations, QueryCache* cache = nullptr,
                           uint32_t* hint = nullptr) const;
  double regionHalfSize() const { return regionHalfSize_; }

  const std::vector<SweptMove>& segments() const;
  const SceneStats& stats() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  double regionHalfSize_ = 0;
};

}  // namespace scallop
