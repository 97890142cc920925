#include "analysis/normal_deviation.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <utility>

#include "analysis/move_line_index.h"
#include "analysis/shadow_grid.h"
#include "analysis/vertex_normals.h"
#include "raycast/grid_frame.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_move.h"

namespace scallop {

namespace {

// Round-off of a dot product or support value of magnitude |v| (mm): bounds are widened
// by it so that culling stays proven.
double margin(double v) {
  return 1e-9 * (1 + std::fabs(v));
}

// The frame of the line through `p` along the unit `n`: u across n from the coordinate
// axis n leans least towards, so that axis-aligned normals give exact rotations.
GridFrame lineFrame(const Vec3& p, const Vec3& n, double depth) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const Vec3 e = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  const Vec3 c = cross(n, e);
  GridFrame frame;
  frame.origin = p;
  frame.normal = n;
  frame.u = c / length(c);
  frame.v = cross(n, frame.u);
  frame.depth = depth;
  return frame;
}

// One cutting move swept on its own in the part frame, for its proven bounds.
struct MoveBounds {
  size_t move;
  Box3 box;
  Box3 grown;  // `box` grown by the round-off of each coordinate
  SweptMove swept;
};

Box3 grownByRoundOff(const Box3& b) {
  return {{b.min.x - margin(b.min.x), b.min.y - margin(b.min.y), b.min.z - margin(b.min.z)},
          {b.max.x + margin(b.max.x), b.max.y + margin(b.max.y), b.max.z + margin(b.max.z)}};
}

// The range [enter, leave] of w where the line p + w n is inside `grown` (a box grown by
// its round-off), or enter > leave.
std::pair<double, double> lineInBox(const Box3& grown, const Vec3& p, const Vec3& n) {
  const double pc[3] = {p.x, p.y, p.z}, nc[3] = {n.x, n.y, n.z};
  const double lo[3] = {grown.min.x, grown.min.y, grown.min.z};
  const double hi[3] = {grown.max.x, grown.max.y, grown.max.z};
  double enter = -HUGE_VAL, leave = HUGE_VAL;
  for (int a = 0; a < 3; ++a) {
    if (nc[a] == 0) {
      if (pc[a] < lo[a] || pc[a] > hi[a]) return {1, 0};
      continue;
    }
    const double t1 = (lo[a] - pc[a]) / nc[a], t2 = (hi[a] - pc[a]) / nc[a];
    enter = std::max(enter, std::min(t1, t2) - margin(t1));
    leave = std::min(leave, std::max(t1, t2) + margin(t2));
  }
  return {enter, leave};
}

// The directions across a line's frame: u, -u, v, -v.
std::array<Vec3, 4> acrossDirections(const GridFrame& f) {
  return {f.u, -f.u, f.v, -f.v};
}

// A move's support values in a line's frame (the same for every line along one normal):
// across it, each grown by its round-off, and along n and -n.
struct FrameSupports {
  std::array<double, 4> across;
  double along, against;
};

FrameSupports frameSupports(const SweptMove& swept, const GridFrame& f) {
  FrameSupports s;
  const std::array<Vec3, 4> across = acrossDirections(f);
  for (size_t k = 0; k < 4; ++k) {
    const double h = swept.support(across[k]);
    s.across[k] = h + margin(h);
  }
  s.along = swept.support(f.normal);
  s.against = swept.support(-f.normal);
  return s;
}

// What the bounds need of one line: its frame and top, the coordinates of its point
// across it (each lowered by its round-off), and n.p and its round-off.
struct LineTerms {
  const GridFrame* frame;
  double top;
  std::array<double, 4> across;
  double np, npMargin;
};

LineTerms lineTerms(const GridFrame& f, double top) {
  LineTerms line{&f, top, {}, dot(f.normal, f.origin), 0};
  const std::array<Vec3, 4> across = acrossDirections(f);
  for (size_t k = 0; k < 4; ++k) {
    const double at = dot(across[k], f.origin);
    line.across[k] = at - margin(at);
  }
  line.npMargin = margin(line.np);
  return line;
}

// A lower bound of w over the move's solid on the line through p along n within
// [-depth, top], or NaN when the solid provably misses that part of the line.
// `supports`: frameSupports of the move in the line's frame.
double lowerBoundOnLine(const MoveBounds& m, const FrameSupports& supports, const LineTerms& line) {
  const GridFrame& f = *line.frame;
  const auto [enter, leave] = lineInBox(m.grown, f.origin, f.normal);
  if (enter > leave || leave < -f.depth || enter > line.top) return NAN;
  // The solid lies between the planes of its support across the line in u and v ...
  for (size_t k = 0; k < 4; ++k)
    if (supports.across[k] < line.across[k]) return NAN;
  // ... and between w = -support(-n) - n.p and support(n) - n.p along it.
  const double highest = supports.along - line.np;
  if (highest + margin(highest) + line.npMargin < -f.depth) return NAN;
  const double lowest = -supports.against - line.np;
  return std::max(enter, lowest - margin(lowest) - line.npMargin);
}

// Move `m` of `path` in the line's frame, as a path of that one move.
ToolPath moveInFrame(const ToolPath& path, const Move& m, const GridFrame& f) {
  ToolPath one;
  Move moved = m;
  for (Pose* pose : {&moved.from, &moved.to}) {
    pose->tip = f.pointToFrame(pose->tip);
    pose->axis = f.directionToFrame(pose->axis);
  }
  if (m.arc > 0 && m.arc <= path.arcs.size()) {
    ArcMotion arc = path.arcs[m.arc - 1];
    arc.centre = f.pointToFrame(arc.centre);
    arc.u = f.directionToFrame(arc.u);
    arc.v = f.directionToFrame(arc.v);
    one.arcs.push_back(arc);
    moved.arc = 1;
  }
  one.moves.push_back(moved);
  return one;
}

// Whether a move's axis points to the normal side all along it in the frame: a slerp
// between two such axes (or an arc's constant axis) never leaves that side.
bool axisOnNormalSide(const Move& moved) {
  return moved.from.axis.z >= 0 && moved.to.axis.z >= 0;
}

struct VertexResult {
  double w;
  VertexDeviation status;
  uint32_t candidates, evaluations;
  int64_t move;  // the path's move that made w; -1: the stock's surface (or none)
};

// The part frame's moves, their boxes and an index of them for the lines' candidate
// search.
struct MoveSet {
  std::vector<MoveBounds> moves;
  std::vector<Box3> boxes;
  double slack = 0;                      // see makeIndex
  std::unique_ptr<MoveLineIndex> index;  // null: every move is a candidate
};

// Normals shared by at least this many vertices (and half the moves) find their
// candidates through a grid of the moves' shadows across the normal (shadow_grid.h).
constexpr size_t kVerticesForGrid = 64;

// The moves swept in a normal's frame that a thread keeps (each ~1.5 KB).
constexpr size_t kSweptMovesKept = 4096;

// One thread's scratch; the heights do not depend on it. Moves are swept in the frame
// of the line's rotation alone (origin at the part's origin), which every vertex with
// the same normal shares, and so are their support values in that frame: consecutive
// vertices with one normal (a flat face; vertices are visited in the order of their
// normals) reuse both. Each swept move keeps the memo of its last plane section, which
// the vertices of a line across it (visited in turn) share. A normal shared by many
// vertices gets a grid of the moves' shadows across it, instead of a BVH ray a vertex.
struct LineScratch {
  std::vector<uint32_t> ids;
  std::vector<std::pair<double, size_t>> order;
  bool hasNormal = false;
  Vec3 normal{0, 0, 0};
  GridFrame rotation;
  bool useGrid = false;
  ShadowGrid grid;
  // Per move, for the current normal where `stamp` is the scratch's (a new normal bumps
  // the scratch's instead of clearing them): its support values, and its sweep in the
  // rotation's frame (an index into `swept`, or -1).
  struct PerMove {
    uint32_t stamp = 0;
    FrameSupports supports;
    int32_t swept = -1;
  };
  std::vector<PerMove> perMove;
  uint32_t stamp = 0;
  struct Swept {
    size_t k;                               // the move
    std::unique_ptr<const SweptMove> move;  // null: k < 0
    SectionMemo memo;
  };
  std::vector<Swept> swept;

  // Forgets the swept moves (they are swept again when needed): at most kSweptMovesKept
  // are kept, a few MB, however many moves a large face meets.
  void forgetSwept() {
    for (const Swept& m : swept) perMove[m.k].swept = -1;
    swept.clear();
  }

  // Makes `n` the current normal, for a run of `vertices` vertices sharing it.
  void useNormal(const Vec3& n, size_t vertices, const MoveSet& set, double depth) {
    if (hasNormal && normal == n) return;
    hasNormal = true;
    normal = n;
    rotation = lineFrame({0, 0, 0}, n, depth);
    swept.clear();
    if (perMove.size() != set.moves.size()) perMove.assign(set.moves.size(), {});
    if (++stamp == 0) {
      for (PerMove& m : perMove) m.stamp = 0;
      stamp = 1;
    }
    useGrid = set.index && vertices >= kVerticesForGrid && 2 * vertices >= set.moves.size() &&
              grid.build(set.boxes, rotation.u, rotation.v, set.slack);
  }
  PerMove& move(size_t k, const MoveSet& set) {
    PerMove& m = perMove[k];
    if (m.stamp != stamp) {
      m.stamp = stamp;
      m.supports = frameSupports(set.moves[k].swept, rotation);
      m.swept = -1;
    }
    return m;
  }
};

VertexResult deviationAt(const Vec3& p, const Vec3& n, size_t groupSize, const ToolPath& path,
                         const Cutter& cutter, const MoveSet& set, const Box3& stock, double depth,
                         LineScratch& scratch) {
  VertexResult r{NAN, VertexDeviation::kUnresolved, 0, 0, -1};
  if (!(length(n) > 0)) return r;
  scratch.useNormal(n, groupSize, set, depth);
  const GridFrame& rotation = scratch.rotation;
  GridFrame f = rotation;  // lineFrame(p, n, depth): the same axes, the origin at p
  f.origin = p;
  const double top = stockExitHeight(stock, f, 0, 0);
  if (std::isnan(top)) {
    r.status = VertexDeviation::kNoMaterial;
    return r;
  }
  // The line in the rotation's frame: the vertical through (x0, y0), w = z - np.
  const double x0 = dot(p, rotation.u), y0 = dot(p, rotation.v), np = dot(p, n);
  const std::vector<MoveBounds>& moves = set.moves;
  const uint32_t* ids = nullptr;
  size_t count = 0;
  if (scratch.useGrid) {
    ids = scratch.grid.boxesAt(x0, y0, count);
  } else if (set.index) {
    set.index->boxesMeeting(p, n, std::min(-depth, top), std::max(-depth, top), scratch.ids);
    ids = scratch.ids.data(), count = scratch.ids.size();
  } else {
    scratch.ids.resize(moves.size());
    for (size_t k = 0; k < moves.size(); ++k) scratch.ids[k] = uint32_t(k);
    ids = scratch.ids.data(), count = scratch.ids.size();
  }
  std::vector<std::pair<double, size_t>>& order = scratch.order;
  order.clear();
  const LineTerms line = lineTerms(f, top);
  for (size_t c = 0; c < count; ++c) {
    const size_t k = ids[c];
    const double bound = lowerBoundOnLine(moves[k], scratch.move(k, set).supports, line);
    if (!std::isnan(bound)) order.emplace_back(bound, k);
  }
  r.candidates = uint32_t(order.size());
  std::sort(order.begin(), order.end());
  double best = top;
  bool unresolved = false;
  for (const auto& [bound, k] : order) {
    if (bound >= best) break;  // this move and every later one stay above `best`
    LineScratch::PerMove& per = scratch.move(k, set);
    if (per.swept < 0) {
      const Move& m = path.moves[moves[k].move];
      const ToolPath one = moveInFrame(path, m, rotation);
      const Cutter& c = path.cutters.empty() ? cutter : path.cutters[m.tool];
      if (scratch.swept.size() >= kSweptMovesKept) scratch.forgetSwept();
      per.swept = int32_t(scratch.swept.size());
      scratch.swept.emplace_back();
      scratch.swept.back().k = k;
      if (axisOnNormalSide(one.moves[0]))
        scratch.swept.back().move =
            std::make_unique<const SweptMove>(c, PoseCurve::ofMove(one, one.moves[0]));
    }
    LineScratch::Swept& swept = scratch.swept[size_t(per.swept)];
    if (!swept.move) {
      unresolved = true;
      continue;
    }
    ++r.evaluations;
    const LowestPoint lp = swept.move->lowestPoint(x0, y0, &swept.memo, best + np);
    if (lp.hit && lp.z - np < best) best = lp.z - np, r.move = int64_t(moves[k].move);
  }
  if (unresolved) return r;
  if (best < -depth) {
    r.w = -depth;
    r.status = VertexDeviation::kCutThrough;
  } else {
    r.w = best;
    r.status = VertexDeviation::kMeasured;
  }
  return r;
}

// The slack of the boxes' index and grid, well above the float rounding of the lines'
// rays (a few 1e-7 of the largest coordinate of the stock, the boxes, the vertices and
// the gouge depth; see MoveLineIndex).
double indexSlack(const std::vector<Box3>& boxes, const Box3& stock, const TriangleMesh& design,
                  double depth) {
  double scale = depth;
  const auto extend = [&](const Vec3& p) {
    scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  };
  extend(stock.min), extend(stock.max);
  for (const Box3& b : boxes) extend(b.min), extend(b.max);
  for (const Vec3& p : design.vertices) extend(p);
  return 1e-5 * (1 + 3 * scale);
}

// The order in which the vertices are visited, and for each place in it the number of
// vertices that share its vertex's normal.
struct VisitOrder {
  std::vector<size_t> vertex;
  std::vector<size_t> sharingNormal;
};

struct NormalHash {
  size_t operator()(const Vec3& n) const {
    uint64_t h = 0x9E3779B97F4A7C15ull;
    for (double c : {n.x + 0.0, n.y + 0.0, n.z + 0.0}) {  // + 0.0: -0 hashes as 0
      uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 0xC2B2AE3D27D4EB4Full;
      h ^= h >> 29;
    }
    return size_t(h);
  }
};

// By normal, so that vertices sharing one follow each other (they share the moves swept
// in its frame), and within a normal by lines of constant u in its frame: a move along
// such a line (on a face with normal +z, u is +y: a raster along x) is cut by one plane
// section for all of them. Normals, lines and the vertices on a line keep the order of
// their first vertex (hash maps: linear in the vertices, no sort).
VisitOrder visitOrder(const TriangleMesh& design, const std::vector<Vec3>& normals, double depth) {
  std::unordered_map<Vec3, uint32_t, NormalHash> groupOf;
  std::vector<Vec3> groupU;  // the rotation frame's u of each normal
  std::vector<size_t> groupSize;
  // Lines: (normal, u) -> line; each line's normal and vertex count.
  const auto lineHash = [](const std::pair<uint32_t, double>& key) {
    return NormalHash{}(Vec3{double(key.first), key.second, 0});
  };
  std::unordered_map<std::pair<uint32_t, double>, uint32_t, decltype(lineHash)> lineOf(16,
                                                                                       lineHash);
  std::vector<uint32_t> lineGroup, lineSize, lineOfVertex(design.vertices.size());
  uint32_t group = 0, line = 0;
  for (size_t i = 0; i < design.vertices.size(); ++i) {
    const Vec3& n = normals[i];
    if (i == 0 || !(n == normals[i - 1])) {
      const auto [it, fresh] = groupOf.try_emplace(n, uint32_t(groupU.size()));
      if (fresh) {
        groupU.push_back(length(n) > 0 ? lineFrame({0, 0, 0}, n, depth).u : Vec3{0, 0, 0});
        groupSize.push_back(0);
      }
      group = it->second;
    }
    ++groupSize[group];
    const auto [it, fresh] = lineOf.try_emplace({group, dot(design.vertices[i], groupU[group])},
                                                uint32_t(lineGroup.size()));
    if (fresh) lineGroup.push_back(group), lineSize.push_back(0);
    line = it->second;
    ++lineSize[line];
    lineOfVertex[i] = line;
  }
  // Each normal's place, then each line's within it, then the vertices.
  std::vector<size_t> next(groupSize.size(), 0);
  for (size_t g = 1; g < groupSize.size(); ++g) next[g] = next[g - 1] + groupSize[g - 1];
  std::vector<size_t> lineNext(lineGroup.size());
  for (size_t l = 0; l < lineGroup.size(); ++l) {
    lineNext[l] = next[lineGroup[l]];
    next[lineGroup[l]] += lineSize[l];
  }
  VisitOrder order;
  order.vertex.resize(design.vertices.size());
  order.sharingNormal.resize(design.vertices.size());
  for (size_t i = 0; i < design.vertices.size(); ++i) {
    const size_t at = lineNext[lineOfVertex[i]]++;
    order.vertex[at] = i;
    order.sharingNormal[at] = groupSize[lineGroup[lineOfVertex[i]]];
  }
  return order;
}

}  // namespace

NormalDeviation normalDeviation(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                const TriangleMesh& design, double gougeDepth,
                                CandidateSearch search) {
  MoveSet set;
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& m = path.moves[k];
    if (m.rapid) continue;
    const Cutter& c = path.cutters.empty() ? cutter : path.cutters[m.tool];
    SweptMove swept(c, PoseCurve::ofMove(path, m));
    const Box3 box = swept.bounds();
    set.moves.push_back({k, box, grownByRoundOff(box), std::move(swept)});
    set.boxes.push_back(box);
  }

  NormalDeviation out;
  out.normals = areaWeightedVertexNormals(design);
  const size_t n = design.vertices.size();
  if (search == CandidateSearch::kIndexed) {
    set.slack = indexSlack(set.boxes, stock, design, gougeDepth);
    set.index = std::make_unique<MoveLineIndex>(set.boxes, set.slack);
  }
  const VisitOrder order = visitOrder(design, out.normals, gougeDepth);
  std::vector<VertexResult> results(n);
  tbb::enumerable_thread_specific<LineScratch> scratches;
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        LineScratch& scratch = scratches.local();
        for (size_t k = r.begin(); k < r.end(); ++k) {
          const size_t v = order.vertex[k];
          results[v] = deviationAt(design.vertices[v], out.normals[v], order.sharingNormal[k], path,
                                   cutter, set, stock, gougeDepth, scratch);
        }
      });

  out.deviation.resize(n);
  out.status.resize(n);
  out.lowestMove.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const VertexResult& r = results[v];
    out.deviation[v] = r.w;
    out.status[v] = r.status;
    out.lowestMove[v] =
        r.status == VertexDeviation::kMeasured || r.status == VertexDeviation::kCutThrough ? r.move
                                                                                           : -1;
    out.cutThrough += r.status == VertexDeviation::kCutThrough;
    out.noMaterial += r.status == VertexDeviation::kNoMaterial;
    out.unresolved += r.status == VertexDeviation::kUnresolved;
    out.candidates += r.candidates;
    out.exactEvaluations += r.evaluations;
  }
  return out;
}

}  // namespace scallop
