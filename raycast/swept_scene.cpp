// Building the culling scene: each segment's tiles with their proven planes and boxes,
// then the tile grid that every query reads (tile_grid.h). The exact heights themselves
// are the kernel's (SweptMove::lowestPoint), asked by scene_queries.cpp.
#include "raycast/swept_scene.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "base/constants.h"
#include "raycast/scene_tiles.h"
#include "raycast/tile_grid.h"

namespace scallop {

using namespace scene_detail;

namespace scene_detail {

// The plane N . p = h_C(N) below a swept solid C, as z >= a + b x + c y (N.z < 0): it
// bounds every height of C from below, everywhere.
TilePlane planeBelow(const SweptMove& seg, const Vec3& N) {
  const double h = seg.support(N);
  return {h / N.z, -N.x / N.z, -N.y / N.z};
}

// The plane to keep for a segment from its exact lowest point at (x, y). Where the
// solid has a usable bottom there, its supporting plane. Where the line misses the
// solid or meets its near-vertical side (the rim of the footprint), a steep plane
// leaning outwards from the move, N = (d, -1e-3) with d the horizontal direction from
// the nearest point of the move's tip path: it rises by 1 mm per um outside the
// footprint, so cells beyond the rim are culled without an evaluation. Returns false
// when neither applies (the point lies on the tip path itself).
bool planeFrom(const SweptMove& seg, const LowestPoint& lp, double x, double y, TilePlane& plane) {
  if (lp.hit && lp.normal.z <= -1e-3) {
    plane = planeBelow(seg, lp.normal);
    return true;
  }
  const Vec3 &a = seg.start(), &b = seg.end();
  const double ux = b.x - a.x, uy = b.y - a.y, uu = ux * ux + uy * uy;
  const double t = uu > 0 ? std::clamp(((x - a.x) * ux + (y - a.y) * uy) / uu, 0.0, 1.0) : 0.0;
  const double dx = x - (a.x + t * ux), dy = y - (a.y + t * uy), dd = std::hypot(dx, dy);
  if (!(dd > 1e-9)) return false;
  plane = planeBelow(seg, normalize(Vec3{dx / dd, dy / dd, -1e-3}));
  return true;
}

// The plane's normal needs no exact evaluation: any downward direction gives a valid
// plane (planeBelow takes the solid's exact support), only a tight one culls well. For
// a whole move's tile (moves shorter than a few cells), the normal of the solid swept by
// the cutter with a vertical axis, in closed form: on the envelope it is perpendicular to
// the move, N = (e N_m + u N_u, N_z) with N_u = -N_z sigma (sigma: the move's slope, u
// its horizontal direction, e across it), and the contact lies Rb + r |N_xy| from the
// axis (the torus, r the corner radius) at the centre line's point r N_u behind it along
// u; beyond the move's ends, the stationary cutter's torus normal. Exact for a ball with
// a vertical axis; for a bull the flat's share (Rb) is taken across the move only, and a
// tilted axis or another profile only loosens the plane. Five of these replace five exact
// evaluations, which were a third of the scene build of a million short moves (B9).
LowestPoint closedFormPlaneHint(const SweptMove& seg, double x, double y) {
  const Vec3 &a = seg.start(), &b = seg.end();
  const Cutter& c = seg.cutter();
  const double r = c.general() ? c.radius : c.cornerRadius;
  const double Rb = c.general() ? 0.0 : c.bottomRadius();
  LowestPoint lp;
  // The stationary cutter at tip (px, py): the torus normal at the horizontal distance
  // from its axis, or nothing beyond its bottom (planeFrom's steep rim plane).
  auto stationary = [&](double px, double py) {
    const double hx = x - px, hy = y - py, h = std::hypot(hx, hy);
    const double sinB = r > 0 ? std::clamp((h - Rb) / r, 0.0, 1.0) : (h > Rb ? 1.0 : 0.0);
    if (sinB >= 1) return;
    const double cosB = std::sqrt(1 - sinB * sinB);
    lp.normal = h > 0 ? Vec3{hx / h * sinB, hy / h * sinB, -cosB} : Vec3{0, 0, -1};
    lp.hit = true;
  };
  const double ux = b.x - a.x, uy = b.y - a.y, w = std::hypot(ux, uy);
  if (!(w > 1e-12)) {
    stationary(a.x, a.y);
    return lp;
  }
  const double ex = ux / w, ey = uy / w, sigma = (b.z - a.z) / w;
  const double along = (x - a.x) * ex + (y - a.y) * ey, across = (x - a.x) * -ey + (y - a.y) * ex;
  const double h = std::fabs(across);
  const double Nm = r > 0 ? std::min(1.0, std::max(0.0, h - Rb) / r) : (h > Rb ? 1.0 : 0.0);
  if (Nm < 1) {
    const double Nz = -std::sqrt((1 - Nm * Nm) / (1 + sigma * sigma)), Nu = -Nz * sigma;
    const double centre = along - r * Nu;  // the centre line's point under the contact
    if (centre >= 0 && centre <= w) {
      const double side = across < 0 ? -1.0 : 1.0;
      lp.normal = {-ey * side * Nm + ex * Nu, ex * side * Nm + ey * Nu, Nz};
      lp.hit = true;
      return lp;
    }
    stationary(centre < 0 ? a.x : b.x, centre < 0 ? a.y : b.y);
    return lp;
  }
  stationary(along < 0.5 * w ? a.x : b.x, along < 0.5 * w ? a.y : b.y);
  return lp;
}

}  // namespace scene_detail

SectionMemo* SweptScene::QueryCache::memoFor(uint32_t segment, double y) {
  uint64_t bits;
  std::memcpy(&bits, &y, sizeof bits);
  const uint64_t h = (uint64_t(segment) * 0x9E3779B97F4A7C15ull) ^ (bits * 0xC2B2AE3D27D4EB4Full);
  return &memo[(h >> 40) % kSlots];
}

double cullingTileSide(double cutterRadius, double moveLength, double boxArea,
                       const SceneOptions& options) {
  if (options.tileSize > 0) return options.tileSize;
  if (options.cellsPerMove < kCellsPerMoveForTiles && moveLength < cutterRadius) return HUGE_VAL;
  // Tiles of R/8 keep the box bounds tight on long moves; a short move gets at most
  // ~N tiles, since bounding costs 5 exact evaluations a tile and the per-cell plane
  // test keeps the culling sharp anyway. Moves shorter than the cutter radius (CAM
  // paths: thousands overlap each cell) get 16: measured on B3, 4x less build time and
  // no more evaluations per cell than with 64; B1's long passes keep 64 (with 16 they
  // need 30% more evaluations per cell).
  const double tiles = moveLength < cutterRadius ? 16 : 64;
  return std::max(cutterRadius / 8, std::sqrt(boxArea / tiles));
}

// --- Building the culling tiles -------------------------------------------------------
// For one segment, over one tile: the swept solid C is convex, so every plane with a
// downward normal N through C's support value h_C(N) lies below all of C; on the tile
// its lowest value is at a corner. The normals come from exact lowest points at the
// tile's centre and corners (each one's supporting plane is tight there).
namespace {

// A segment's xy box cut into nx x ny tiles (cullingTileSide); nx = 0: the segment never
// goes below the stock top.
struct SegmentGrid {
  Box3 box;
  int nx = 0, ny = 0;
  bool whole = false;  // one tile for the whole move (cullingTileSide's dense programs)
};

// Writes the tiles of segment k that meet its footprint and can go below the stock top
// to `out` (room for nx * ny) and returns how many; `evaluations` counts the exact ones.
uint32_t boundSegmentTiles(const SweptMove& seg, uint32_t k, const SegmentGrid& grid,
                           double stockTop, TileBox* out, size_t& evaluations) {
  const Box3& box = grid.box;
  const int nx = grid.nx, ny = grid.ny;
  if (nx == 0) return 0;
  const double tx = (box.max.x - box.min.x) / nx, ty = (box.max.y - box.min.y) / ny;

  // The footprint's support in 16 horizontal directions, to drop tiles it misses. A
  // single tile is the segment's box, which holds the footprint: none to drop (B9: a
  // quarter of the scene's instructions went to these supports).
  constexpr int kDirs = 16;
  const int dirsUsed = nx * ny > 1 ? kDirs : 0;
  double footprint[kDirs];
  Vec3 dirs[kDirs];
  for (int i = 0; i < dirsUsed; ++i) {
    const double a = 2 * kPi * i / kDirs;
    dirs[i] = {std::cos(a), std::sin(a), 0};
    footprint[i] = seg.support(dirs[i]);
  }

  uint32_t kept = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double x0 = box.min.x + i * tx, x1 = i + 1 == nx ? box.max.x : x0 + tx;
      const double y0 = box.min.y + j * ty, y1 = j + 1 == ny ? box.max.y : y0 + ty;
      const double cx[4] = {x0, x1, x0, x1}, cy[4] = {y0, y0, y1, y1};
      bool disjoint = false;
      for (int d = 0; d < dirsUsed && !disjoint; ++d) {
        double lo = HUGE_VAL;
        for (int c = 0; c < 4; ++c) lo = std::min(lo, dirs[d].x * cx[c] + dirs[d].y * cy[c]);
        disjoint = lo > footprint[d] + 1e-9;
      }
      if (disjoint) continue;

      double lower = box.min.z;
      TileBox t;
      t.planes = 0;
      // A tile's planes from its centre and corners; a whole move's from its centre and
      // 0.18 of its box's width towards each side: its corners lie outside the
      // footprint, whose steep rim planes bound nothing inside it, while these follow the
      // bottom's slopes on all four sides (B9 at 4 mm, cast instructions: corners 3.7x,
      // 0.25 of the width 1.08x, 0.1 1.09x, 0.32 1.23x those of 0.18).
      const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
      const double qx = 0.18 * (x1 - x0), qy = 0.18 * (y1 - y0);
      const double sx[5] = {mx, grid.whole ? mx - qx : x0, grid.whole ? mx + qx : x1,
                            grid.whole ? mx : x0, grid.whole ? mx : x1};
      const double sy[5] = {my, grid.whole ? my : y0, grid.whole ? my : y0,
                            grid.whole ? my - qy : y1, grid.whole ? my + qy : y1};
      for (int s = 0; s < kSamplesPerTile; ++s) {
        const LowestPoint lp =
            grid.whole ? closedFormPlaneHint(seg, sx[s], sy[s]) : seg.planeHint(sx[s], sy[s]);
        evaluations += !grid.whole;
        TilePlane plane;
        if (!planeFrom(seg, lp, sx[s], sy[s], plane)) continue;
        t.plane[t.planes++] = plane;
        double planeMin = HUGE_VAL;
        for (int c = 0; c < 4; ++c)
          planeMin = std::min(planeMin, plane.a + plane.b * cx[c] + plane.c * cy[c]);
        lower = std::max(lower, planeMin);
      }
      if (lower >= stockTop) continue;  // the whole tile stays above the stock
      t.lower[0] = roundDown(x0), t.lower[1] = roundDown(y0), t.lower[2] = roundDown(lower);
      t.upper[0] = roundUp(x1), t.upper[1] = roundUp(y1);
      t.upper[2] = std::max(t.lower[2], roundUp(std::min(box.max.z, stockTop)));
      t.segment = k;
      out[kept++] = t;
    }
  }
  return kept;
}

// Segments are bounded a batch at a time into a scratch of at most about this many
// tiles (~40 MB), reused: the whole program's scratch, sized for every tile before the
// footprint and the stock drop a quarter of them, was a third of B9's peak memory.
constexpr size_t kScratchTiles = size_t(1) << 18;

}  // namespace

void SweptScene::Impl::buildTiles(const SceneOptions& options) {
  const double stockTop = options.stockTop;
  // Each segment's grid of tiles first: it bounds how many tiles the segment can keep, so
  // every segment of a batch writes its tiles into its own slice of one scratch array (no
  // small allocations on the worker threads, whose freed memory their malloc arenas
  // would keep resident through the cast: 40 to 110 MB on B3).
  std::vector<SegmentGrid> grids(segments.size());
  tbb::parallel_for(size_t(0), segments.size(), [&](size_t k) {
    const SweptMove& seg = segments[k];
    SegmentGrid& g = grids[k];
    g.box = seg.bounds();
    if (g.box.min.z >= stockTop) return;  // never below the stock top: cannot cut
    const Box3& box = g.box;
    const double T = cullingTileSide(seg.cutter().radius, length(seg.end() - seg.start()),
                                     (box.max.x - box.min.x) * (box.max.y - box.min.y), options);
    g.whole = T == HUGE_VAL;
    g.nx = std::max(1, int(std::ceil((box.max.x - box.min.x) / T)));
    g.ny = std::max(1, int(std::ceil((box.max.y - box.min.y) / T)));
  });
  size_t most = 0;  // tiles before any is dropped: the kept ones' bound
  for (const SegmentGrid& g : grids) most += size_t(g.nx) * size_t(g.ny);
  // Room for every tile, of which only those kept are ever written (the allocator leaves
  // the rest untouched, so the pages past them are never resident).
  tiles.reserve(most);
  TileStorage scratch;
  std::vector<size_t> slice, offset;
  std::vector<uint32_t> kept;
  std::vector<size_t> evalsPerSegment;
  for (size_t first = 0; first < segments.size();) {
    // The batch [first, last): at least one segment, up to kScratchTiles tiles.
    slice.assign(1, 0);
    size_t last = first;
    while (last < segments.size() &&
           (last == first ||
            slice.back() + size_t(grids[last].nx) * size_t(grids[last].ny) <= kScratchTiles)) {
      slice.push_back(slice.back() + size_t(grids[last].nx) * size_t(grids[last].ny));
      ++last;
    }
    const size_t n = last - first;
    if (scratch.size() < slice.back()) scratch.resize(slice.back());
    kept.assign(n, 0);
    evalsPerSegment.assign(n, 0);
    tbb::parallel_for(size_t(0), n, [&](size_t b) {
      const size_t k = first + b;
      kept[b] = boundSegmentTiles(segments[k], uint32_t(k), grids[k], stockTop,
                                  scratch.data() + slice[b], evalsPerSegment[b]);
    });
    // Appended in segment order so the scene is the same whatever the threads did: each
    // segment's tiles go to their offset, copied in parallel (a serial append, growing
    // the vector as it went, was a third of B3's scene build).
    offset.assign(n + 1, tiles.size());
    for (size_t b = 0; b < n; ++b) {
      offset[b + 1] = offset[b] + kept[b];
      stats.boundEvaluations += evalsPerSegment[b];
    }
    tiles.resize(offset.back());
    tbb::parallel_for(size_t(0), n, [&](size_t b) {
      std::copy(scratch.begin() + std::ptrdiff_t(slice[b]),
                scratch.begin() + std::ptrdiff_t(slice[b] + kept[b]),
                tiles.begin() + std::ptrdiff_t(offset[b]));
    });
    first = last;
  }
  stats.tiles = tiles.size();
}

SweptScene::SweptScene(std::vector<SweptMove> segments, const SceneOptions& options)
    : impl_(std::make_unique<Impl>()), regionHalfSize_(options.regionHalfSize) {
  const auto t0 = std::chrono::steady_clock::now();
  impl_->segments = std::move(segments);
  if (impl_->segments.size() > UINT32_MAX) throw std::runtime_error("too many segments");
  for (SweptMove& s : impl_->segments) {
    s.setContactKnotSpacing(options.contactKnotSpacing);
    impl_->turningMoves = impl_->turningMoves || s.turning();
  }
  impl_->stats.segments = impl_->segments.size();
  impl_->buildTiles(options);
  impl_->grid = std::make_unique<TileGrid>();
  impl_->grid->build(impl_->tiles, options.regionHalfSize);
  SceneStats& stats = impl_->stats;
  for (const SweptMove& s : impl_->segments)
    stats.moveBytes += SweptMove::bytesPerMove(s.turning(), s.teeth() != nullptr, s.hasTipBall(),
                                               s.teeth() && s.teeth()->counterClockwise());
  // The tiles kept (their storage's capacity past them is never touched).
  stats.tileBytes = impl_->tiles.size() * sizeof(TileBox);
  stats.gridBytes = impl_->grid->bytes();
  stats.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

SweptScene::~SweptScene() = default;

const std::vector<SweptMove>& SweptScene::segments() const {
  return impl_->segments;
}
const SceneStats& SweptScene::stats() const {
  return impl_->stats;
}

}  // namespace scallop
