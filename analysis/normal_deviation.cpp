#include "analysis/normal_deviation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>
#include <unordered_map>
#include <utility>

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

// A lower bound of w over the move's solid on the line through p along n within
// [-depth, top], or NaN when the solid provably misses that part of the line.
double lowerBoundOnLine(const MoveBounds& m, const GridFrame& f, double top) {
  const auto [enter, leave] = lineInBox(m.box, f.origin, f.normal);
  if (enter > leave || leave < -f.depth || enter > top) return NAN;
  // The solid lies between the planes of its support across the line in u and v ...
  for (const Vec3& d : {f.u, -f.u, f.v, -f.v}) {
    const double h = m.swept.support(d), at = dot(d, f.origin);
    if (h + margin(h) < at - margin(at)) return NAN;
  }
  // ... and between w = -support(-n) - n.p and support(n) - n.p along it.
  const double np = dot(f.normal, f.origin);
  const double highest = m.swept.support(f.normal) - np;
  if (highest + margin(highest) + margin(np) < -f.depth) return NAN;
  const double lowest = -m.swept.support(-f.normal) - np;
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

// One thread's scratch. Moves are swept in the frame of the line's rotation alone (origin
// at the part's origin), which every vertex with the same normal shares: consecutive
// vertices with one normal (a flat face, vertices visited in the order of their normals)
// reuse the swept moves. The heights do not depend on it: the frame is the normal's.
struct LineScratch {
  std::vector<std::pair<double, size_t>> order;
  Vec3 normal{0, 0, 0};
  std::unordered_map<size_t, std::unique_ptr<const SweptMove>> swept;  // null: k < 0
};

VertexResult deviationAt(const Vec3& p, const Vec3& n, const ToolPath& path, const Cutter& cutter,
                         const std::vector<MoveBounds>& moves, const Box3& stock, double depth,
                         LineScratch& scratch) {
  VertexResult r{NAN, VertexDeviation::kUnresolved, 0, 0};
  if (!(length(n) > 0)) return r;
  const GridFrame f = lineFrame(p, n, depth);
  const double top = stockExitHeight(stock, f, 0, 0);
  if (std::isnan(top)) {
    r.status = VertexDeviation::kNoMaterial;
    return r;
  }
  std::vector<std::pair<double, size_t>>& order = scratch.order;
  order.clear();
  for (size_t k = 0; k < moves.size(); ++k) {
    const double bound = lowerBoundOnLine(moves[k], f, top);
    if (!std::isnan(bound)) order.emplace_back(bound, k);
  }
  r.candidates = uint32_t(order.size());
  std::sort(order.begin(), order.end());
  if (!(scratch.normal == n)) scratch.swept.clear(), scratch.normal = n;
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
        slot->second = std::make_unique<const SweptMove>(c, PoseCurve::ofMove(one, one.moves[0]));
    }
    if (!slot->second) {
      unresolved = true;
      continue;
    }
    ++r.evaluations;
    const LowestPoint lp = slot->second->lowestPoint(x0, y0, nullptr, best + np);
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

}  // namespace

NormalDeviation normalDeviation(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                const TriangleMesh& design, double gougeDepth) {
  std::vector<MoveBounds> moves;
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& m = path.moves[k];
    if (m.rapid) continue;
    const Cutter& c = path.cutters.empty() ? cutter : path.cutters[m.tool];
    SweptMove swept(c, PoseCurve::ofMove(path, m));
    const Box3 box = swept.bounds();
    moves.push_back({k, box, std::move(swept)});
  }

  NormalDeviation out;
  out.normals = areaWeightedVertexNormals(design);
  const size_t n = design.vertices.size();
  // Vertices in the order of their normals, so that those sharing one follow each other.
  std::vector<size_t> byNormal(n);
  for (size_t v = 0; v < n; ++v) byNormal[v] = v;
  const auto key = [&](size_t v) {
    const Vec3& a = out.normals[v];
    return std::tuple(a.x, a.y, a.z, v);
  };
  std::sort(byNormal.begin(), byNormal.end(), [&](size_t a, size_t b) { return key(a) < key(b); });
  std::vector<VertexResult> results(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256),
                    [&](const tbb::blocked_range<size_t>& r) {
                      LineScratch scratch;
                      for (size_t k = r.begin(); k < r.end(); ++k) {
                        const size_t v = byNormal[k];
                        results[v] = deviationAt(design.vertices[v], out.normals[v], path, cutter,
                                                 moves, stock, gougeDepth, scratch);
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
