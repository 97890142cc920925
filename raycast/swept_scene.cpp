// The Embree side of scallop, walked through once (after Embree's minimal tutorial):
// a device, one scene, one user geometry whose primitives are (segment, xy tile)
// boxes, a bounds callback that hands Embree those boxes, and an intersect callback
// that runs the exact double-precision height and shortens the ray.
#include "raycast/swept_scene.h"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace scallop {

namespace {

// A tile primitive: its Embree box (world coordinates, float), its segment, and the
// supporting planes found while bounding it. Each plane z = a + b x + c y lies below
// the whole swept solid, so max over planes at the exact cell centre is a lower bound
// that is much tighter than the box's (which holds for the whole tile): a candidate
// whose bound is not below the best height so far needs no exact evaluation.
struct TilePlane {
  double a, b, c;
};
constexpr int kPlanesPerTile = 5;
// Exact evaluations (centre first, then corners) that give each tile its planes.
constexpr int kSamplesPerTile = 5;
struct TileBox {
  float lower[3];
  float upper[3];
  uint32_t segment;
  uint32_t planes;
  TilePlane plane[kPlanesPerTile];
};

// Slack that absorbs float rounding of a coordinate of magnitude |v| (mm): a few float
// ulps plus a nanometre. Culling must stay conservative after conversion to float.
float slack(double v) {
  return float(8.0 * std::fabs(v) * 0x1p-23 + 1e-6);
}
float roundDown(double v) {
  return std::nextafter(float(v), -HUGE_VALF) - slack(v);
}
float roundUp(double v) {
  return std::nextafter(float(v), HUGE_VALF) + slack(v);
}

// The ray's context carries the exact (double) cell centre and the best height so far;
// Embree hands it back to the intersect callback (the first member must be Embree's).
struct CellContext {
  RTCIntersectContext embree;
  double x, y;     // exact cell centre, mm
  double originZ;  // the ray starts here, below every box
  double best;     // lowest exact height found so far, mm
  uint64_t evaluations;
  SweptScene::QueryCache* cache;  // may be null
  uint32_t winner;                // segment of `best`, or UINT32_MAX
  // Gathering mode (gatherCandidates): collect tiles that may be lowest somewhere in
  // the region [x0, x1] x [y0, y1] below `best`, without shortening the ray.
  bool gathering;
  double x0, y0, x1, y1;
  std::vector<uint32_t>* gathered;
};

// The lower bound of a tile's planes at one point, or over a rectangle (each plane's
// minimum over a rectangle is at a corner).
double planeBoundAt(const TileBox& t, double x, double y) {
  double bound = -HUGE_VAL;
  for (uint32_t k = 0; k < t.planes; ++k)
    bound = std::max(bound, t.plane[k].a + t.plane[k].b * x + t.plane[k].c * y);
  return bound;
}
double planeMinOver(const TilePlane& p, double x0, double y0, double x1, double y1) {
  return p.a + std::min(p.b * x0, p.b * x1) + std::min(p.c * y0, p.c * y1);
}
double planeBoundOver(const TileBox& t, double x0, double y0, double x1, double y1) {
  double bound = -HUGE_VAL;
  for (uint32_t k = 0; k < t.planes; ++k)
    bound = std::max(bound, planeMinOver(t.plane[k], x0, y0, x1, y1));
  return bound;
}
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

// The cutoff to evaluate a guessed winner with (a neighbour's). A turning move's search
// first tries to prove the move stays above its cutoff (ray clearance, swept_move.cpp
// step 4a), which a winner always fails: a guess, right 95 % of the time on B3, skips
// it. Heights do not depend on the cutoff, only whether a loser costs more.
double hintCutoff(const SweptMove& seg, double best) {
  return seg.turning() && !seg.teeth() ? HUGE_VAL : best;
}

// The section memo of a constant-axis move for the cell's row (null without a cache, and
// for a turning move, which keeps none: no hash for it).
SectionMemo* memoOf(SweptScene::QueryCache* cache, const SweptMove& move, uint32_t segment,
                    double y) {
  return cache && !move.turning() ? cache->memoFor(segment, y) : nullptr;
}

// Plane values are exact up to double round-off; this margin (mm) absorbs it. (Steep
// planes have coefficients up to 1e3; their round-off stays below 1e-11 mm here.)
double planeSlack(double v) {
  return 1e-9 * (1 + std::fabs(v));
}

}  // namespace

struct SweptScene::Impl {
  std::vector<SweptMove> segments;
  std::vector<TileBox> tiles;
  SceneStats stats;
  double originZ = 0;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string lastError;

  void buildTiles(const SceneOptions& options);
  void buildEmbree();
};

namespace {

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto* impl = static_cast<const SweptScene::Impl*>(args->geometryUserPtr);
  const TileBox& t = impl->tiles[args->primID];
  RTCBounds* b = args->bounds_o;
  b->lower_x = t.lower[0], b->lower_y = t.lower[1], b->lower_z = t.lower[2];
  b->upper_x = t.upper[0], b->upper_y = t.upper[1], b->upper_z = t.upper[2];
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  // scallop only traces single rays (rtcIntersect1), so N == 1.
  if (!args->valid[0]) return;
  const auto* impl = static_cast<const SweptScene::Impl*>(args->geometryUserPtr);
  auto* cell = reinterpret_cast<CellContext*>(args->context);
  const TileBox& tile = impl->tiles[args->primID];
  if (cell->gathering) {
    const double bound = planeBoundOver(tile, cell->x0, cell->y0, cell->x1, cell->y1);
    if (bound - planeSlack(bound) < cell->best) cell->gathered->push_back(args->primID);
    return;
  }
  const double bound = planeBoundAt(tile, cell->x, cell->y);
  if (bound - planeSlack(bound) >= cell->best) return;
  const SweptMove& seg = impl->segments[tile.segment];
  ++cell->evaluations;
  SectionMemo* memo = memoOf(cell->cache, seg, tile.segment, cell->y);
  const LowestPoint lp = seg.lowestPoint(cell->x, cell->y, memo, cell->best);
  if (!lp.hit || !(lp.z < cell->best)) return;
  cell->best = lp.z;
  cell->winner = tile.segment;
  // Shorten the ray to (just above) the new best: boxes that start higher are culled,
  // while any segment that could still be lower has a box starting below it.
  auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
  rayhit->ray.tfar = roundUp(lp.z - cell->originZ);
  rayhit->hit.geomID = args->geomID;
  rayhit->hit.primID = args->primID;
}

// Embree reports errors through a C callback; exceptions must not cross it, so the
// message is kept and thrown after the call returns.
void deviceError(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  *last = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

}  // namespace

SectionMemo* SweptScene::QueryCache::memoFor(uint32_t segment, double y) {
  uint64_t bits;
  std::memcpy(&bits, &y, sizeof bits);
  const uint64_t h = (uint64_t(segment) * 0x9E3779B97F4A7C15ull) ^ (bits * 0xC2B2AE3D27D4EB4Full);
  return &memo[(h >> 40) % kSlots];
}

double cullingTileSide(double cutterRadius, double moveLength, double boxArea,
                       const SceneOptions& options) {
  if (options.tileSize > 0) return options.tileSize;
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
void SweptScene::Impl::buildTiles(const SceneOptions& options) {
  const double stockTop = options.stockTop;
  std::vector<std::vector<TileBox>> perSegment(segments.size());
  std::vector<size_t> evalsPerSegment(segments.size(), 0);
  tbb::parallel_for(size_t(0), segments.size(), [&](size_t k) {
    const SweptMove& seg = segments[k];
    const Box3 box = seg.bounds();
    if (box.min.z >= stockTop) return;  // never below the stock top: cannot cut
    const double T = cullingTileSide(seg.cutter().radius, length(seg.end() - seg.start()),
                                     (box.max.x - box.min.x) * (box.max.y - box.min.y), options);
    const int nx = std::max(1, int(std::ceil((box.max.x - box.min.x) / T)));
    const int ny = std::max(1, int(std::ceil((box.max.y - box.min.y) / T)));
    const double tx = (box.max.x - box.min.x) / nx, ty = (box.max.y - box.min.y) / ny;

    // The footprint's support in 16 horizontal directions, to drop tiles it misses.
    constexpr int kDirs = 16;
    double footprint[kDirs];
    Vec3 dirs[kDirs];
    for (int i = 0; i < kDirs; ++i) {
      const double a = 2 * 3.14159265358979323846 * i / kDirs;
      dirs[i] = {std::cos(a), std::sin(a), 0};
      footprint[i] = seg.support(dirs[i]);
    }

    std::vector<TileBox>& out = perSegment[k];
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double x0 = box.min.x + i * tx, x1 = i + 1 == nx ? box.max.x : x0 + tx;
        const double y0 = box.min.y + j * ty, y1 = j + 1 == ny ? box.max.y : y0 + ty;
        const double cx[4] = {x0, x1, x0, x1}, cy[4] = {y0, y0, y1, y1};
        bool disjoint = false;
        for (int d = 0; d < kDirs && !disjoint; ++d) {
          double lo = HUGE_VAL;
          for (int c = 0; c < 4; ++c) lo = std::min(lo, dirs[d].x * cx[c] + dirs[d].y * cy[c]);
          disjoint = lo > footprint[d] + 1e-9;
        }
        if (disjoint) continue;

        double lower = box.min.z;
        TileBox t;
        t.planes = 0;
        const double sx[5] = {0.5 * (x0 + x1), x0, x1, x0, x1};
        const double sy[5] = {0.5 * (y0 + y1), y0, y0, y1, y1};
        for (int s = 0; s < kSamplesPerTile; ++s) {
          const LowestPoint lp = seg.planeHint(sx[s], sy[s]);
          ++evalsPerSegment[k];
          TilePlane plane;
          if (!planeFrom(seg, lp, sx[s], sy[s], plane)) continue;
          t.plane[t.planes++] = plane;
          double planeMin = HUGE_VAL;
          for (int c = 0; c < 4; ++c)
            planeMin = std::min(planeMin, plane.a + plane.b * cx[c] + plane.c * cy[c]);
          lower = std::max(lower, planeMin);
        }
        if (lower >= stockTop) continue;  // the whole tile stays above the stock
        // Grown by the query region's half size, so that one ray at a region's centre
        // meets every tile that overlaps the region (gatherCandidates).
        const double g = options.regionHalfSize;
        t.lower[0] = roundDown(x0 - g), t.lower[1] = roundDown(y0 - g),
        t.lower[2] = roundDown(lower);
        t.upper[0] = roundUp(x1 + g), t.upper[1] = roundUp(y1 + g);
        t.upper[2] = std::max(t.lower[2], roundUp(std::min(box.max.z, stockTop)));
        t.segment = uint32_t(k);
        out.push_back(t);
      }
    }
  });
  // Concatenate in segment order so the scene is the same whatever the threads did.
  for (size_t k = 0; k < perSegment.size(); ++k) {
    tiles.insert(tiles.end(), perSegment[k].begin(), perSegment[k].end());
    stats.boundEvaluations += evalsPerSegment[k];
  }
  stats.tiles = tiles.size();
}

void SweptScene::Impl::buildEmbree() {
  device = rtcNewDevice(nullptr);
  if (!device) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device, deviceError, &lastError);
  scene = rtcNewScene(device);
  // Robust traversal: a vertical ray exactly on a box face must not slip through.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, unsigned(tiles.size()));
  rtcSetGeometryUserData(geom, this);
  rtcSetGeometryBoundsFunction(geom, boundsCallback, this);
  rtcSetGeometryIntersectFunction(geom, intersectCallback);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE || !lastError.empty())
    throw std::runtime_error(lastError.empty() ? "Embree: scene build failed" : lastError);
}

SweptScene::SweptScene(std::vector<SweptMove> segments, const SceneOptions& options)
    : impl_(std::make_unique<Impl>()), regionHalfSize_(options.regionHalfSize) {
  const auto t0 = std::chrono::steady_clock::now();
  impl_->segments = std::move(segments);
  if (impl_->segments.size() > UINT32_MAX) throw std::runtime_error("too many segments");
  for (SweptMove& s : impl_->segments) s.setContactKnotSpacing(options.contactKnotSpacing);
  impl_->stats.segments = impl_->segments.size();
  double zMin = options.stockTop;
  for (const SweptMove& s : impl_->segments) zMin = std::min(zMin, s.bounds().min.z);
  impl_->originZ = zMin - 1;
  impl_->buildTiles(options);
  impl_->buildEmbree();
  impl_->stats.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

SweptScene::~SweptScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

const std::vector<SweptMove>& SweptScene::segments() const {
  return impl_->segments;
}
const SceneStats& SweptScene::stats() const {
  return impl_->stats;
}

namespace {

// One upward ray from below every box at (x, y), ending at `ceiling`.
RTCRayHit upwardRay(double x, double y, double originZ, double ceiling) {
  RTCRayHit rh;
  rh.ray.org_x = float(x), rh.ray.org_y = float(y), rh.ray.org_z = float(originZ);
  rh.ray.dir_x = 0, rh.ray.dir_y = 0, rh.ray.dir_z = 1;
  rh.ray.tnear = 0;
  rh.ray.tfar = roundUp(ceiling - originZ);
  rh.ray.time = 0;
  rh.ray.mask = ~0u;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

CellContext makeContext(double x, double y, double originZ, double ceiling,
                        SweptScene::QueryCache* cache) {
  CellContext cell;
  rtcInitIntersectContext(&cell.embree);
  cell.x = x, cell.y = y;
  cell.originZ = originZ;
  cell.best = ceiling;
  cell.evaluations = 0;
  cell.cache = cache;
  cell.winner = UINT32_MAX;
  cell.gathering = false;
  cell.x0 = cell.y0 = cell.x1 = cell.y1 = 0;
  cell.gathered = nullptr;
  return cell;
}

}  // namespace

double SweptScene::lowestHeight(double x, double y, double ceiling, uint64_t& evaluations,
                                QueryCache* cache, uint32_t* winner) const {
  const uint32_t guess = winner ? *winner : UINT32_MAX;
  if (winner) *winner = UINT32_MAX;
  if (impl_->tiles.empty()) return ceiling;
  CellContext cell = makeContext(x, y, impl_->originZ, ceiling, cache);
  // The guessed segment's height, found first, shortens the ray before it starts.
  if (guess < impl_->segments.size()) {
    SectionMemo* memo = memoOf(cache, impl_->segments[guess], guess, y);
    ++cell.evaluations;
    const LowestPoint lp =
        impl_->segments[guess].lowestPoint(x, y, memo, hintCutoff(impl_->segments[guess], ceiling));
    if (lp.hit && lp.z < ceiling) cell.best = lp.z, cell.winner = guess;
  }
  RTCRayHit rh = upwardRay(x, y, impl_->originZ, cell.best);
  rtcIntersect1(impl_->scene, &cell.embree, &rh);
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
  CellContext cell = makeContext(cx, cy, impl_->originZ, ceiling, nullptr);
  cell.gathering = true;
  cell.x0 = x0, cell.y0 = y0, cell.x1 = x1, cell.y1 = y1;
  cell.gathered = &tiles;
  RTCRayHit rh = upwardRay(cx, cy, impl_->originZ, ceiling);
  rtcIntersect1(impl_->scene, &cell.embree, &rh);
  // One tile per segment is enough: every tile's planes bound its whole segment. Kept in
  // a canonical order, so the work done does not depend on Embree's traversal order.
  std::sort(tiles.begin(), tiles.end(), [&](uint32_t a, uint32_t b) {
    const uint32_t sa = impl_->tiles[a].segment, sb = impl_->tiles[b].segment;
    return sa != sb ? sa < sb : a < b;
  });
  for (uint32_t id : tiles) {
    const uint32_t segment = impl_->tiles[id].segment;
    if (candidates.empty() || candidates.back().segment != segment) {
      candidates.emplace_back();
      candidates.back().tile = id, candidates.back().segment = segment;
    }
  }
  for (Candidate& cand : candidates) {
    const SweptMove& seg = impl_->segments[cand.segment];
    if (seg.turning()) cand.tip = tipPlaneBound(seg.curve(), x0, y0, x1, y1);
  }
}

void SweptScene::tightenCandidates(std::vector<Candidate>& candidates, double x, double y,
                                   uint64_t& evaluations, QueryCache* cache) const {
  for (Candidate& cand : candidates) {
    const SweptMove& seg = impl_->segments[cand.segment];
    SectionMemo* memo = memoOf(cache, seg, cand.segment, y);
    ++evaluations;
    // The envelope's plane: below the envelope, so below the teeth's crossings too.
    const LowestPoint lp =
        seg.turning() ? seg.locatedPlaneHint(x, y) : seg.envelopeLowestPoint(x, y, memo);
    TilePlane plane;
    if (planeFrom(seg, lp, x, y, plane)) cand.a = plane.a, cand.b = plane.b, cand.c = plane.c;
  }
}

void SweptScene::orderForBlock(const std::vector<Candidate>& candidates, double x0, double y0,
                               double x1, double y1, std::vector<BlockEntry>& order) const {
  order.clear();
  for (uint32_t k = 0; k < candidates.size(); ++k) {
    const Candidate& cand = candidates[k];
    // A turning move's tip-plane bound stands in for its tile's planes here (B3: 1 % fewer
    // instructions; the cells still consult both).
    const double tip = cand.tip.minOver(x0, y0, x1, y1);
    double bound = std::max(planeMinOver({cand.a, cand.b, cand.c}, x0, y0, x1, y1), tip);
    if (tip == -HUGE_VAL)
      bound = std::max(bound, planeBoundOver(impl_->tiles[cand.tile], x0, y0, x1, y1));
    order.push_back({bound - planeSlack(bound), k});
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
  double best = ceiling;
  uint32_t winner = UINT32_MAX;
  auto evaluate = [&](uint32_t k, double cutoff) {
    const uint32_t segment = candidates[k].segment;
    ++evaluations;
    const SweptMove& move = impl_->segments[segment];
    SectionMemo* memo = memoOf(cache, move, segment, y);
    // A same-pass neighbour of the best move so far (the next or previous move of the
    // path) proves it stays above the cutoff first from the pose the two share.
    double anchor = NAN;
    if (winner != UINT32_MAX) {
      const uint32_t w = candidates[winner].segment;
      if (segment == w + 1) anchor = 0;
      if (segment + 1 == w) anchor = 1;
    }
    const LowestPoint lp = move.lowestPoint(x, y, memo, cutoff, anchor);
    if (lp.hit && lp.z < best) best = lp.z, winner = k;
  };
  // The candidate's own plane (from the region's centre) is usually the tightest and
  // alone often prunes it; the tile's planes are consulted only when it does not, and a
  // turning move's tip-plane bound (tip_plane_bound.h) only when neither does: it
  // follows a bottom face as it turns, which world-fixed planes cannot. Each bound is
  // lowered by its round-off margin as it is made.
  const auto lowered = [](double v) { return v - planeSlack(v); };
  auto safeBound = [&](const Candidate& cand) {
    double bound = lowered(cand.a + cand.b * x + cand.c * y);
    if (bound < best) bound = std::max(bound, lowered(planeBoundAt(impl_->tiles[cand.tile], x, y)));
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
