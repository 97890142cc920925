// The culling scene's queries: a cell's lowest height from the tile grid's list under
// its point (ascending bounds, each exact height shortening the rest), and the region
// queries (gather the candidates of a square of cells from the tile grid, tighten
// their planes, order them per block, and each cell's branch and bound among them).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "raycast/scene_tiles.h"
#include "raycast/swept_scene.h"
#include "raycast/tile_grid.h"
#include "sweep/tip_plane_bound.h"

namespace scallop {

using namespace scene_detail;

namespace {

// True only if `move` is proven above z on every vertical line through the rectangle
// [x0, x1] x [y0, y1]: the ray clearance of the disc round its centre that holds it
// (SweptMove::clearsAbove; false for constant-axis moves and for no bound).
bool provenAboveOver(const SweptMove& move, double x0, double y0, double x1, double y1, double z) {
  if (!(z < HUGE_VAL)) return false;
  const double radius = 0.5 * std::hypot(x1 - x0, y1 - y0) * (1 + 1e-12) + 1e-12;
  return move.clearsAbove(0.5 * (x0 + x1), 0.5 * (y0 + y1), z, radius);
}

CellContext makeContext(double x, double y, double ceiling, SweptScene::QueryCache* cache) {
  CellContext cell;
  cell.x = x, cell.y = y;
  cell.best = ceiling;
  cell.evaluations = 0;
  cell.cache = cache;
  cell.winner = UINT32_MAX;
  return cell;
}

}  // namespace

bool scene_detail::tryTile(const SweptScene::Impl& impl, const TileBox& tile, CellContext& cell) {
  const double bound = planeBoundAt(tile, cell.x, cell.y);
  if (bound - planeSlack(bound) >= cell.best) return false;
  const SweptMove& seg = impl.segments[tile.segment];
  ++cell.evaluations;
  SectionMemo* memo = memoOf(cell.cache, seg, tile.segment, cell.y);
  const LowestPoint lp = seg.lowestPoint(cell.x, cell.y, memo, cell.best);
  if (!lp.hit || !(lp.z < cell.best)) return false;
  cell.best = lp.z;
  cell.winner = tile.segment;
  return true;
}

double SweptScene::lowestHeight(double x, double y, double ceiling, uint64_t& evaluations,
                                QueryCache* cache, uint32_t* winner) const {
  const uint32_t guess = winner ? *winner : UINT32_MAX;
  if (winner) *winner = UINT32_MAX;
  if (impl_->tiles.empty()) return ceiling;
  CellContext cell = makeContext(x, y, ceiling, cache);
  // The guessed segment's height, found first, prunes the list before it is read.
  if (guess < impl_->segments.size()) {
    SectionMemo* memo = memoOf(cache, impl_->segments[guess], guess, y);
    ++cell.evaluations;
    const LowestPoint lp =
        impl_->segments[guess].lowestPoint(x, y, memo, hintCutoff(impl_->segments[guess], ceiling));
    if (lp.hit && lp.z < ceiling) cell.best = lp.z, cell.winner = guess;
  }
  const TileStorage& tiles = impl_->tiles;
  // Until a first height is found, the turning moves whose tip passes nearest the point
  // first: they reach it, while many whose tile holds the point do not (their planes,
  // sloping away, would sort them first), and a turning move's proof that it misses costs
  // several times more against a high cutoff than against a low one (B6: 8x; Embree's
  // traversal, front to back through a spatial hierarchy, happened to meet the near moves
  // early). Constant-axis moves miss cheaply: they wait for the walk below.
  bool turningTried = false;  // every turning tile under the ceiling asked, none below it
  if (cell.winner == UINT32_MAX && impl_->turningMoves) {
    thread_local std::vector<std::pair<double, uint32_t>> nearest;
    nearest.clear();
    impl_->grid->forEachUnder(
        tiles, x, y, [&] { return cell.best; },
        [&](uint32_t tile) {
          const SweptMove& m = impl_->segments[tiles[tile].segment];
          if (!m.turning()) return;
          const double ax = m.start().x, ay = m.start().y;
          const double dx = m.end().x - ax, dy = m.end().y - ay, len2 = dx * dx + dy * dy;
          const double u =
              len2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0;
          nearest.emplace_back(std::hypot(ax + u * dx - x, ay + u * dy - y), tile);
        });
    std::sort(nearest.begin(), nearest.end());
    for (size_t k = 0; k < nearest.size() && cell.winner == UINT32_MAX; ++k)
      tryTile(*impl_, tiles[nearest[k].second], cell);
    turningTried = cell.winner == UINT32_MAX;
  }
  // Then the grid's list under the point, in ascending bound, each height shortening the
  // rest (those tried above are asked again if their bound allows: cheap against the
  // lower cutoff).
  impl_->grid->forEachUnder(
      tiles, x, y, [&] { return cell.best; },
      [&](uint32_t tile) {
        if (turningTried && impl_->segments[tiles[tile].segment].turning()) return;
        tryTile(*impl_, tiles[tile], cell);
      });
  evaluations += cell.evaluations;
  if (winner) *winner = cell.winner;
  return std::min(cell.best, ceiling);
}

void SweptScene::gatherCandidates(double x0, double y0, double x1, double y1, double ceiling,
                                  std::vector<Candidate>& candidates) const {
  candidates.clear();
  if (impl_->tiles.empty()) return;
  if (std::max(x1 - x0, y1 - y0) > 2 * regionHalfSize_ * (1 + 1e-12))
    throw std::logic_error("gatherCandidates: region larger than the scene was built for");
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  thread_local std::vector<uint32_t> tiles;
  tiles.clear();
  // Every tile whose grown box stands over the centre and whose planes can go below the
  // ceiling somewhere in the region (tile_grid.h lists them by a bound of their own).
  impl_->grid->forEachOver(impl_->tiles, cx, cy, ceiling, [&](uint32_t id) {
    const double bound = planeBoundOver(impl_->tiles[id], x0, y0, x1, y1);
    if (bound - planeSlack(bound) < ceiling) tiles.push_back(id);
  });
  // One tile per segment is enough: every tile's planes bound its whole segment. Kept in
  // a canonical order, so the work done does not depend on the order the grid lists them in.
  std::sort(tiles.begin(), tiles.end(), [&](uint32_t a, uint32_t b) {
    const uint32_t sa = impl_->tiles[a].segment, sb = impl_->tiles[b].segment;
    return sa != sb ? sa < sb : a < b;
  });
  // Turning moves proven above the ceiling on every line of the region are left out
  // before anything else is spent on them: on B3 the moves of other passes, most of
  // them.
  uint32_t last = UINT32_MAX;
  for (uint32_t id : tiles) {
    const uint32_t segment = impl_->tiles[id].segment;
    if (segment == last) continue;
    last = segment;
    const SweptMove& seg = impl_->segments[segment];
    if (provenAboveOver(seg, x0, y0, x1, y1, ceiling)) continue;
    candidates.emplace_back();
    candidates.back().tile = id, candidates.back().segment = segment;
    candidates.back().teeth = seg.teeth() != nullptr;
    // A constant-axis kernel's tip plane is its lowest tip's: no tighter than its tile's
    // planes (B7: its tip ball, 1 % more instructions a cell with it).
    if (seg.turning() && !seg.takesSectionMemo())
      candidates.back().tip = tipPlaneBound(seg.curve(), x0, y0, x1, y1);
  }
}

void SweptScene::tightenCandidates(std::vector<Candidate>& candidates, double x, double y,
                                   uint64_t& evaluations, QueryCache* cache) const {
  // The contacts of the last region's candidates, in segment order like the candidates.
  static const std::vector<std::pair<uint32_t, double>> kNone;
  const auto& last = cache ? cache->contacts : kNone;
  if (cache) cache->nextContacts.clear();
  size_t m = 0;
  for (Candidate& cand : candidates) {
    const SweptMove& seg = impl_->segments[cand.segment];
    SectionMemo* memo = memoOf(cache, seg, cand.segment, y);
    ++evaluations;
    while (m < last.size() && last[m].first < cand.segment) ++m;
    const double tStart = m < last.size() && last[m].first == cand.segment ? last[m].second : 0.5;
    // The envelope's plane: below the envelope, so below the teeth's crossings too.
    const LowestPoint lp =
        seg.turning() ? seg.locatedPlaneHint(x, y, tStart) : seg.envelopeLowestPoint(x, y, memo);
    if (cache && lp.hit && seg.turning()) cache->nextContacts.emplace_back(cand.segment, lp.t);
    TilePlane plane;
    if (planeFrom(seg, lp, x, y, plane)) cand.a = plane.a, cand.b = plane.b, cand.c = plane.c;
  }
  if (cache) cache->contacts.swap(cache->nextContacts);
}

void SweptScene::orderForBlock(const std::vector<Candidate>& candidates, double x0, double y0,
                               double x1, double y1, std::vector<BlockEntry>& order,
                               double zTop) const {
  order.clear();
  for (uint32_t k = 0; k < candidates.size(); ++k) {
    const Candidate& cand = candidates[k];
    // A turning move's tip-plane bound stands in for its tile's planes here (B3: 1 % fewer
    // instructions; its cells consult the tip-plane bound again).
    const double tip = cand.tip.minOver(x0, y0, x1, y1);
    double bound = std::max(planeMinOver({cand.a, cand.b, cand.c}, x0, y0, x1, y1), tip);
    if (tip == -HUGE_VAL)
      bound = std::max(bound, planeBoundOver(impl_->tiles[cand.tile], x0, y0, x1, y1));
    bound -= planeSlack(bound);
    // Moves that cannot go below zTop anywhere in the block are no candidates of it. The
    // planes of a turning move lie tens of um below it (docs/performance-history.md,
    // seventh round), and most of those a cell would otherwise settle one by one (other passes'
    // moves, 80 um or more above, or not over the cell at all) the block's ray clearance
    // settles at once.
    if (bound >= zTop || provenAboveOver(impl_->segments[cand.segment], x0, y0, x1, y1, zTop))
      continue;
    order.push_back({bound, k});
  }
  std::sort(order.begin(), order.end(), [](const BlockEntry& p, const BlockEntry& q) {
    return p.bound != q.bound ? p.bound < q.bound : p.candidate < q.candidate;
  });
}

double SweptScene::lowestHeightAmong(const std::vector<Candidate>& candidates,
                                     const std::vector<BlockEntry>& block, double x, double y,
                                     double ceiling, uint64_t& evaluations, QueryCache* cache,
                                     uint32_t* hint) const {
  // Branch and bound: the hinted candidate is evaluated first; then, walking the block's
  // candidates up to the first whose block bound cannot beat the best height found,
  // each one's plane bound at (x, y), and the survivors in ascending order of it,
  // stopping at the first bound that cannot beat the best height. Every candidate
  // skipped has a bound, hence a height, at or above the returned one, so the minimum
  // does not depend on the order, the block or the hint.
  thread_local std::vector<std::pair<double, uint32_t>> order;
  order.clear();
  // winnerT: the pose parameter of the best's contact; NaN for a constant-axis kernel's
  // best (a tip ball's too), whose LowestPoint carries none (so no rule below fires for it).
  double best = ceiling, winnerT = NAN;
  uint32_t winner = UINT32_MAX;
  auto evaluate = [&](uint32_t k, double cutoff) {
    const uint32_t segment = candidates[k].segment;
    ++evaluations;
    const SweptMove& move = impl_->segments[segment];
    SectionMemo* memo = memoOf(cache, move, segment, y);
    // A same-pass neighbour of the best move so far (the next or previous move of the
    // path) proves it stays above the cutoff first from the pose the two share. Where
    // the best's contact is at that very pose (a pass bending there) the line touches
    // the neighbour's cutter at the cutoff and the proof cannot close: the neighbour is
    // evaluated without it (hintCutoff's reason; B3: 1.1 % fewer instructions).
    double anchor = NAN;
    if (winner != UINT32_MAX) {
      const uint32_t w = candidates[winner].segment;
      if (segment == w + 1) anchor = 0;
      if (segment + 1 == w) anchor = 1;
      constexpr double kAtPose = 1e-9;  // t: the shared pose, to round-off (a cost rule only)
      if ((anchor == 0 && winnerT >= 1 - kAtPose) || (anchor == 1 && winnerT <= kAtPose))
        cutoff = hintCutoff(move, cutoff);
    }
    const LowestPoint lp = move.lowestPoint(x, y, memo, cutoff, anchor);
    if (lp.hit && lp.z < best)
      best = lp.z, winner = k, winnerT = move.takesSectionMemo() ? NAN : lp.t;
  };
  // The candidate's own plane (from the region's centre) is usually the tightest and
  // alone often prunes it; a turning move's tip-plane bound (tip_plane_bound.h) is
  // consulted only when it does not: it follows a bottom face as it turns, which
  // world-fixed planes cannot. The tile's planes, already in the block's bound, are
  // asked again at the cell only for a move with teeth, whose evaluation costs a
  // hundred of the envelope's (elsewhere they pruned too little for their cost: B1 17 %
  // and B3 2 % faster without them). Each bound is lowered by its round-off margin as
  // it is made.
  const auto lowered = [](double v) { return v - planeSlack(v); };
  auto safeBound = [&](const Candidate& cand) {
    double bound = lowered(cand.a + cand.b * x + cand.c * y);
    if (bound < best && cand.teeth)
      bound = std::max(bound, lowered(planeBoundAt(impl_->tiles[cand.tile], x, y)));
    if (bound < best) bound = std::max(bound, lowered(cand.tip.at(x, y)));
    return bound;
  };
  const uint32_t first = hint && *hint < candidates.size() ? *hint : UINT32_MAX;
  if (first != UINT32_MAX && safeBound(candidates[first]) < best)
    evaluate(first, hintCutoff(impl_->segments[candidates[first].segment], best));
  for (const BlockEntry& entry : block) {
    if (entry.bound >= best) break;
    const uint32_t k = entry.candidate;
    if (k == first) continue;
    const double bound = safeBound(candidates[k]);
    if (bound < best) order.emplace_back(bound, k);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [bound, k] : order) {
    if (bound >= best) break;
    evaluate(k, best);
  }
  if (hint) *hint = winner;
  return best;
}

}  // namespace scallop
