#include "analysis/peripheral_strategy.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

namespace {}

const char* toString(PostureClass c) {
  switch (c) {
    case PostureClass::FreeInitial:
      return "free_initial";
    case PostureClass::Inclined:
      return "inclined";
    case PostureClass::Reversed:
      return "reversed";
    case PostureClass::NonMachinable:
      return "non_machinable";
  }
  return "?";
}

const char* toString(InclinationAxis a) {
  return a == InclinationAxis::Normal ? "normal" : "feed";
}

Pose peripheralPose(const Vec3& cc, const Vec3& n, const Vec3& f, double alphaDeg,
                    InclinationAxis axis, const Cutter& cutter, double ccAxialPosition) {
  const Vec3 t = cross(f, n);  // §2.2: T = F x N
  const double ca = std::cos(alphaDeg * kRadPerDeg), sa = std::sin(alphaDeg * kRadPerDeg);
  Vec3 a, toCentre;  // tool axis, and the unit vector from the cc-point to the axis
  if (axis == InclinationAxis::Normal) {
    // Eq. (2) about Z_T (the normal through the cc-point): n x t = f.
    a = t * ca + f * sa;
    toCentre = n;
  } else {
    // About the feed line through the cc-point, t tilting towards n (away from the
    // surface); the whole tool turns, so the direction to its axis turns with it.
    a = t * ca + n * sa;
    toCentre = n * ca - t * sa;
  }
  a = normalize(a);
  const Vec3 onAxis = cc + toCentre * cutter.radius;  // the axis point level with cc
  return {onAxis - a * (ccAxialPosition * cutter.fluteLength), a};
}

namespace {

Vec3 unitAxis(char c) {
  return c == 'x' ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
}
double coord(const Vec3& p, char c) {
  return c == 'x' ? p.x : p.y;
}

struct Piece {
  Vec3 p, q;  // ordered along the feed
  uint32_t triangle;
  double key;  // feed coordinate of the midpoint, for ordering
};

}  // namespace

std::vector<CcPoint> slicingCcPoints(const TriangleMesh& mesh, const StrategyOptions& options,
                                     double spacing, std::vector<double>* planesOut) {
  const char feed = options.feedAxis;
  const char cross_ = feed == 'x' ? 'y' : 'x';
  const Vec3 planeNormal = unitAxis(cross_), feedDir = unitAxis(feed);
  const Box3 box = mesh.bounds();
  const double lo = coord(box.min, cross_), hi = coord(box.max, cross_);
  // §2.1: planes spaced by the effective tool length, centred on the part so that
  // neither rim gets a plane exactly on its boundary edges.
  const int64_t count = std::max<int64_t>(1, int64_t(std::ceil((hi - lo) / spacing - 1e-9)));
  if (count > 1000000)
    throw InputError("--slice-spacing", "gives more than a million slicing planes");
  std::vector<double> planes;
  for (int64_t k = 0; k < count; ++k)
    planes.push_back(0.5 * (lo + hi) + (double(k) - 0.5 * double(count - 1)) * spacing);
  if (planesOut) *planesOut = planes;

  std::vector<CcPoint> out;
  for (size_t pi = 0; pi < planes.size(); ++pi) {
    const double c = planes[pi];
    std::vector<Piece> pieces;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& f = mesh.triangles[t];
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = coord(mesh.vertices[f[k]], cross_) - c;
      // A vertex on the plane counts as above it: each crossing is found once.
      Vec3 hit[2];
      int nh = 0;
      for (int k = 0; k < 3 && nh < 2; ++k) {
        uint32_t ia = f[k], ib = f[(k + 1) % 3];
        double da = d[k], db = d[(k + 1) % 3];
        if ((da < 0) == (db < 0)) continue;
        // Canonical edge order: both facets of an edge compute the same point bit for bit.
        if (ia > ib) std::swap(ia, ib), std::swap(da, db);
        const Vec3& a = mesh.vertices[ia];
        const Vec3& b = mesh.vertices[ib];
        hit[nh++] = a + (b - a) * (da / (da - db));
      }
      if (nh != 2) continue;
      const Vec3 dir = cross(planeNormal, mesh.normals[t]);
      if (!(length(dir) > 1e-12)) continue;
      Vec3 p = hit[0], q = hit[1];
      if (dot(q - p, feedDir) < 0) std::swap(p, q);
      if (p == q) continue;
      pieces.push_back({p, q, t, 0.5 * (coord(p, feed) + coord(q, feed))});
    }
    std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
      return a.key != b.key ? a.key < b.key : a.triangle < b.triangle;
    });
    int line = -1;
    for (size_t k = 0; k < pieces.size(); ++k) {
      const Piece& s = pieces[k];
      // A new connected piece of the slicing line unless this one starts where the
      // previous one ended (a fold or a hole breaks the line).
      if (k == 0 || !(pieces[k - 1].q == s.p)) ++line;
      Vec3 f = normalize(cross(planeNormal, mesh.normals[s.triangle]));
      if (dot(f, feedDir) < 0 || (dot(f, feedDir) == 0 && f.z < 0)) f = -f;
      const double len = length(s.q - s.p);
      const int n =
          options.ccStep > 0 ? std::max(1, int(std::ceil(len / options.ccStep - 1e-9))) : 1;
      for (int i = 0; i < n; ++i) {
        CcPoint cc;
        cc.plane = int(pi);
        cc.line = line;
        cc.point = s.p + (s.q - s.p) * ((i + 0.5) / n);
        cc.normal = mesh.normals[s.triangle];
        cc.feed = f;
        cc.triangle = s.triangle;
        out.push_back(cc);
      }
    }
  }
  return out;
}

namespace {

struct Search {
  const MeshIndex& index;
  const Cutter& cutter;
  const StrategyOptions& opt;
  double testLength;

  bool vertexFree(const Pose& pose, const std::vector<uint32_t>& vertices) const {
    const Cylinder c{pose.tip, pose.axis, cutter.radius, testLength};
    for (uint32_t v : vertices)
      if (vertexInside(index.mesh().vertices[v], c, opt.vertexTolerance)) return false;
    return true;
  }
  double exact(const Pose& pose, const std::vector<uint32_t>& tris, int64_t* deepest) const {
    const Penetration p = cylinderPenetration(
        index.mesh(), tris, {pose.tip, pose.axis, cutter.radius, cutter.fluteLength});
    if (deepest) *deepest = p.triangle;
    return p.depth;
  }

  PostureResult run(const CcPoint& cc) const {
    PostureResult r;
    r.cc = cc;
    const Vec3& n = cc.normal;
    r.kNegative = cross(cc.feed, n).z < 0;
    const double sigma = r.kNegative ? -1.0 : 1.0;  // primary feed: T = (sigma F) x N has k >= 0

    // One Embree query serves every posture of this cc-point: each is a rotation
    // about a line through the cc-point, so the whole tool stays within
    // R + hypot(R, m L) of it (m: the longer part of the flute beyond the cc level).
    const double m = std::max(opt.ccAxialPosition, 1 - opt.ccAxialPosition);
    const double len = std::max(cutter.fluteLength, testLength);
    std::vector<uint32_t> tris;
    index.trianglesNear(cc.point, cutter.radius + std::hypot(cutter.radius, m * len), tris);
    std::vector<uint32_t> verts;
    for (uint32_t t : tris)
      for (uint32_t v : index.mesh().triangles[t]) verts.push_back(v);
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());

    const Pose initial = peripheralPose(cc.point, n, cc.feed * sigma, 0, opt.inclinationAxis,
                                        cutter, opt.ccAxialPosition);
    r.initialVertexFree = vertexFree(initial, verts);
    r.initialExactDepth = exact(initial, tris, nullptr);

    const int steps = int(std::floor(opt.inclinationMaxDeg / opt.inclinationStepDeg + 1e-9));
    for (int o = 0; o < 2; ++o) {
      const Vec3 f = cc.feed * (o == 0 ? sigma : -sigma);
      for (int k = 0; k <= steps; ++k) {
        for (double sign : {1.0, -1.0}) {
          if (sign < 0 && (k == 0 || !opt.inclineBothWays)) continue;
          const double alpha = sign * k * opt.inclinationStepDeg;
          const Pose pose = o == 0 && k == 0
                                ? initial
                                : peripheralPose(cc.point, n, f, alpha, opt.inclinationAxis, cutter,
                                                 opt.ccAxialPosition);
          if (!vertexFree(pose, verts)) continue;
          r.verdict = o == 1 ? PostureClass::Reversed
                             : (k == 0 ? PostureClass::FreeInitial : PostureClass::Inclined);
          r.reversed = o == 1;
          r.inclinationDeg = alpha;
          r.feedUsed = f;
          r.pose = pose;
          r.vertexFree = true;
          r.exactDepth = exact(pose, tris, &r.deepestTriangle);
          return r;
        }
      }
    }
    r.verdict = PostureClass::NonMachinable;
    r.feedUsed = cc.feed * sigma;
    r.pose = initial;
    r.exactDepth = exact(initial, tris, &r.deepestTriangle);
    return r;
  }
};

// Group key of §2.4: the feed sense of the posture relative to the slicing line's
// +feed direction (0 for non-machinable).
int groupKey(const PostureResult& p) {
  if (p.verdict == PostureClass::NonMachinable) return 0;
  return dot(p.feedUsed, p.cc.feed) > 0 ? 1 : -1;
}

}  // namespace

StrategyResult runPeripheralStrategy(const MeshIndex& index, const Cutter& cutter,
                                     const StrategyOptions& options) {
  if (cutter.type != CutterType::Flat)
    throw InputError("tool.type", "peripheral milling (seed 004) needs a flat (cylinder) cutter");
  if (!(options.inclinationStepDeg > 0) || !(options.inclinationMaxDeg >= 0) ||
      options.inclinationMaxDeg > 90)
    throw InputError("--inclination-step/--inclination-max",
                     "need step > 0 and 0 <= max <= 90 deg");
  if (!(options.ccAxialPosition >= 0 && options.ccAxialPosition <= 1))
    throw InputError("--cc-position", "must be in [0, 1] (a fraction of the flute length)");
  if (options.feedAxis != 'x' && options.feedAxis != 'y')
    throw InputError("--feed", "must be x or y");
  const double spacing = options.sliceSpacing > 0 ? options.sliceSpacing : cutter.fluteLength;
  if (!std::isfinite(spacing)) throw InputError("--slice-spacing", "must be a finite length in mm");

  StrategyResult result;
  const std::vector<CcPoint> ccs = slicingCcPoints(index.mesh(), options, spacing, &result.planes);
  const Search search{index, cutter, options,
                      options.vertexTestLength > 0 ? options.vertexTestLength : cutter.fluteLength};
  result.postures.resize(ccs.size());
  tbb::parallel_for(size_t(0), ccs.size(),
                    [&](size_t i) { result.postures[i] = search.run(ccs[i]); });

  StrategySummary& s = result.summary;
  s.ccPoints = ccs.size();
  s.planes = result.planes.size();
  double depthSum = 0;
  for (size_t i = 0; i < result.postures.size(); ++i) {
    const PostureResult& p = result.postures[i];
    s.kNegative += p.kNegative;
    s.initialVertexInterference += !p.initialVertexFree;
    s.initialExactGouging += p.initialExactDepth > options.gougeTolerance;
    switch (p.verdict) {
      case PostureClass::FreeInitial:
        ++s.freeInitial;
        break;
      case PostureClass::Inclined:
        ++s.inclined;
        break;
      case PostureClass::Reversed:
        ++s.reversed;
        break;
      case PostureClass::NonMachinable:
        ++s.nonMachinable;
        break;
    }
    const int key = groupKey(p);
    const bool newGroup = i == 0 || result.postures[i - 1].cc.plane != p.cc.plane ||
                          result.postures[i - 1].cc.line != p.cc.line ||
                          groupKey(result.postures[i - 1]) != key;
    if (newGroup) {
      if (key == 0)
        ++s.groupsNonMachinable;
      else if (key > 0)
        ++s.groupsForward;
      else
        ++s.groupsBackward;
    }
    if (key == 0) continue;
    ++s.checkedPostures;
    if (p.exactDepth > options.gougeTolerance) {
      ++s.gougingPostures;
      s.missedByVertexTest += p.vertexFree;
      depthSum += p.exactDepth;
      s.maxDepth = std::max(s.maxDepth, p.exactDepth);
    }
    // The tool path: join to the previous posture of the same group, else start anew.
    std::vector<Move>& moves = result.path.moves;
    if (newGroup) {
      if (!moves.empty()) moves.push_back({moves.back().to, p.pose, true});
      moves.push_back({p.pose, p.pose, false});
    } else {
      const Pose from = moves.back().to;
      if (moves.back().from.tip == from.tip && moves.back().from.axis == from.axis &&
          !moves.back().rapid)
        moves.back().to = p.pose;  // replace the group's zero-length opening move
      else
        moves.push_back({from, p.pose, false});
    }
  }
  s.meanDepth = s.gougingPostures ? depthSum / double(s.gougingPostures) : 0;
  return result;
}

}  // namespace scallop
