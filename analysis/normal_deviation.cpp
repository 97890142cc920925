#include "analysis/normal_deviation.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "analysis/move_line_index.h"
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
  SweptMove swept;
};

// The range [enter, leave] of w where the line p + w n is inside `box` (grown by its
// round-off), or enter > leave.
std::pair<double, double> lineInBox(const Box3& box, const Vec3& p, const Vec3& n) {
  const double pc[3] = {p.x, p.y, p.z}, nc[3] = {n.x, n.y, n.z};
  const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
  double enter = -HUGE_VAL, leave = HUGE_VAL;
  for (int a = 0; a < 3; ++a) {
    const double l = lo[a] - margin(lo[a]), h = hi[a] + margin(hi[a]);
    if (nc[a] == 0) {
      if (pc[a] < l || pc[a] > h) return {1, 0};
      continue;
    }
    const double t1 = (l - pc[a]) / nc[a], t2 = (h - pc[a]) / nc[a];
    enter = std::max(enter, std::min(t1, t2) - margin(t1));
    leave = std::min(leave, std::max(t1, t2) + margin(t2));
  }
  return {enter, leave};
}

// The support values of a move in the six directions of a line's frame: u, -u, v, -v,
// n, -n (the same for every line along one normal).
using FrameSupports = std::array<double, 6>;

FrameSupports frameSupports(const SweptMove& swept, const GridFrame& f) {
  return {swept.support(f.u),  swept.support(-f.u),     swept.support(f.v),
          swept.support(-f.v), swept.support(f.normal), swept.support(-f.normal)};
}

// A lower bound of w over the move's solid on the line through p along n within
// [-depth, top], or NaN when the solid provably misses that part of the line.
// `supports`: frameSupports of the move in the line's frame.
double lowerBoundOnLine(const MoveBounds& m, const FrameSupports& supports, const GridFrame& f,
                        double top) {
  const auto [enter, leave] = lineInBox(m.box, f.origin, f.normal);
  if (enter > leave || leave < -f.depth || enter > top) return NAN;
  // The solid lies between the planes of its support across the line in u and v ...
  const Vec3 across[4] = {f.u, -f.u, f.v, -f.v};
  for (size_t k = 0; k < 4; ++k) {
    const double h = supports[k], at = dot(across[k], f.origin);
    if (h + margin(h) < at - margin(at)) return NAN;
  }
  // ... and between w = -support(-n) - n.p and support(n) - n.p along it.
  const double np = dot(f.normal, f.origin);
  const double highest = supports[4] - np;
  if (highest + margin(highest) + margin(np) < -f.depth) return NAN;
  const double lowest = -supports[5] - np;
  return std::max(enter, lowest - margin(lowest) - margin(np));
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
};

// One thread's scratch; the heights do not depend on it. Moves are swept in the frame
// of the line's rotation alone (origin at the part's origin), which every vertex with
// the same normal shares, and so are their support values in that frame: consecutive
// vertices with one normal (a flat face; vertices are visited in the order of their
// normals) reuse both. Each swept move keeps the memo of its last plane section, which
// the vertices of a line across it (visited in turn) share.
struct LineScratch {
  std::vector<uint32_t> ids;
  std::vector<std::pair<double, size_t>> order;
  bool hasNormal = false;
  Vec3 normal{0, 0, 0};
  // The support values of move k along the current normal, valid where supportStamp[k]
  // is `stamp` (a new normal bumps it instead of clearing them).
  std::vector<FrameSupports> supports;
  std::vector<uint32_t> supportStamp;
  uint32_t stamp = 0;
  struct Swept {
    std::unique_ptr<const SweptMove> move;  // null: k < 0
    SectionMemo memo;
  };
  std::unordered_map<size_t, Swept> swept;

  void useNormal(const Vec3& n, size_t moves) {
    if (hasNormal && normal == n) return;
    hasNormal = true;
    normal = n;
    swept.clear();
    if (supportStamp.size() != moves) supports.assign(moves, {}), supportStamp.assign(moves, 0);
    if (++stamp == 0) std::fill(supportStamp.begin(), supportStamp.end(), 0), stamp = 1;
  }
};

// The part frame's moves, and an index of their boxes for the lines' candidate search.
struct MoveSet {
  std::vector<MoveBounds> moves;
  std::unique_ptr<MoveLineIndex> index;  // null: every move is a candidate
};

VertexResult deviationAt(const Vec3& p, const Vec3& n, const ToolPath& path, const Cutter& cutter,
                         const MoveSet& set, const Box3& stock, double depth,
                         LineScratch& scratch) {
  VertexResult r{NAN, VertexDeviation::kUnresolved, 0, 0};
  if (!(length(n) > 0)) return r;
  const GridFrame f = lineFrame(p, n, depth);
  const double top = stockExitHeight(stock, f, 0, 0);
  if (std::isnan(top)) {
    r.status = VertexDeviation::kNoMaterial;
    return r;
  }
  const std::vector<MoveBounds>& moves = set.moves;
  scratch.useNormal(n, moves.size());
  std::vector<uint32_t>& ids = scratch.ids;
  if (set.index) {
    set.index->boxesMeeting(p, n, std::min(-depth, top), std::max(-depth, top), ids);
  } else {
    ids.resize(moves.size());
    for (size_t k = 0; k < moves.size(); ++k) ids[k] = uint32_t(k);
  }
  std::vector<std::pair<double, size_t>>& order = scratch.order;
  order.clear();
  for (const uint32_t k : ids) {
    if (scratch.supportStamp[k] != scratch.stamp) {
      scratch.supports[k] = frameSupports(moves[k].swept, f);
      scratch.supportStamp[k] = scratch.stamp;
    }
    const double bound = lowerBoundOnLine(moves[k], scratch.supports[k], f, top);
    if (!std::isnan(bound)) order.emplace_back(bound, k);
  }
  r.candidates = uint32_t(order.size());
  std::sort(order.begin(), order.end());
  const GridFrame rotation = lineFrame({0, 0, 0}, n, depth);
  // The line in the rotation's frame: the vertical through (x0, y0), w = z - np.
  const double x0 = dot(p, rotation.u), y0 = dot(p, rotation.v), np = dot(p, n);
  double best = top;
  bool unresolved = false;
  for (const auto& [bound, k] : order) {
    if (bound >= best) break;  // this move and every later one stay above `best`
    auto [slot, fresh] = scratch.swept.try_emplace(k);
    if (fresh) {
      const Move& m = path.moves[moves[k].move];
      const ToolPath one = moveInFrame(path, m, rotation);
      const Cutter& c = path.cutters.empty() ? cutter : path.cutters[m.tool];
      if (axisOnNormalSide(one.moves[0]))
        slot->second.move =
            std::make_unique<const SweptMove>(c, PoseCurve::ofMove(one, one.moves[0]));
    }
    if (!slot->second.move) {
      unresolved = true;
      continue;
    }
    ++r.evaluations;
    const LowestPoint lp = slot->second.move->lowestPoint(x0, y0, &slot->second.memo, best + np);
    if (lp.hit && lp.z - np < best) best = lp.z - np;
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

// The index of the moves' boxes, its slack well above the float rounding of the lines'
// rays (a few 1e-7 of the largest coordinate of the stock, the boxes, the vertices and
// the gouge depth; see MoveLineIndex).
std::unique_ptr<MoveLineIndex> makeIndex(const std::vector<MoveBounds>& moves, const Box3& stock,
                                         const TriangleMesh& design, double depth) {
  double scale = depth;
  const auto extend = [&](const Vec3& p) {
    scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  };
  extend(stock.min), extend(stock.max);
  std::vector<Box3> boxes;
  boxes.reserve(moves.size());
  for (const MoveBounds& m : moves) extend(m.box.min), extend(m.box.max), boxes.push_back(m.box);
  for (const Vec3& p : design.vertices) extend(p);
  return std::make_unique<MoveLineIndex>(boxes, 1e-5 * (1 + 3 * scale));
}

// The order in which the vertices are visited: by normal, so that those sharing one
// follow each other (they share the moves swept in its frame), then along the lines of
// constant u in that frame: a move along such a line (on a face with normal +z, u is +y:
// a raster along x) is cut by one plane section for all of them.
std::vector<size_t> visitOrder(const TriangleMesh& design, const std::vector<Vec3>& normals,
                               double depth) {
  struct Key {
    Vec3 n;
    double u, v;
    size_t index;
  };
  std::vector<Key> keys(design.vertices.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const Vec3& n = normals[i];
    Key& key = keys[i];
    key.n = n, key.index = i, key.u = 0, key.v = 0;
    if (!(length(n) > 0)) continue;
    const GridFrame rotation = lineFrame({0, 0, 0}, n, depth);
    key.u = dot(design.vertices[i], rotation.u);
    key.v = dot(design.vertices[i], rotation.v);
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return std::tie(a.n.x, a.n.y, a.n.z, a.u, a.v, a.index) <
           std::tie(b.n.x, b.n.y, b.n.z, b.u, b.v, b.index);
  });
  std::vector<size_t> order(keys.size());
  for (size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].index;
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
    set.moves.push_back({k, box, std::move(swept)});
  }

  NormalDeviation out;
  out.normals = areaWeightedVertexNormals(design);
  const size_t n = design.vertices.size();
  if (search == CandidateSearch::kIndexed)
    set.index = makeIndex(set.moves, stock, design, gougeDepth);
  const std::vector<size_t> order = visitOrder(design, out.normals, gougeDepth);
  std::vector<VertexResult> results(n);
  tbb::enumerable_thread_specific<LineScratch> scratches;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256),
                    [&](const tbb::blocked_range<size_t>& r) {
                      LineScratch& scratch = scratches.local();
                      for (size_t k = r.begin(); k < r.end(); ++k) {
                        const size_t v = order[k];
                        results[v] = deviationAt(design.vertices[v], out.normals[v], path, cutter,
                                                 set, stock, gougeDepth, scratch);
                      }
                    });

  out.deviation.resize(n);
  out.status.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const VertexResult& r = results[v];
    out.deviation[v] = r.w;
    out.status[v] = r.status;
    out.cutThrough += r.status == VertexDeviation::kCutThrough;
    out.noMaterial += r.status == VertexDeviation::kNoMaterial;
    out.unresolved += r.status == VertexDeviation::kUnresolved;
    out.candidates += r.candidates;
    out.exactEvaluations += r.evaluations;
  }
  return out;
}

}  // namespace scallop
