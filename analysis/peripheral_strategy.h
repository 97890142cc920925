// Seed 004 (Syaefudin, Kiswanto & Baskoro, "Development of Tool Orientation Strategy
// with Alternative Orientation and Non-machinable Area Identification in 5-Axis
// Peripheral Milling of a Sculptured Surface based on a Faceted Models"), §2 steps
// 1-4, for a cylinder (flat) cutter on a triangle mesh, followed by the exact check of
// every posture it accepts (analysis/gouge_check.h).
//
// Step 1 (§2.1): slicing planes perpendicular to the cross-feed axis, spaced by the
//   effective tool length; each piece of a slicing line inside one facet gives a
//   cc-point (its midpoint) with that facet's normal N, and the feed direction F is
//   the slicing line's direction (plane normal x N), pointing along +feed axis.
// Step 2 (§2.2): the initial tool vector T = F x N; the cylinder's side is tangent to
//   the facet at the cc-point: the axis passes through cc + R N.
// Step 3 (§2.3): interference when a facet vertex lies inside the tool (the TCS test
//   0 <= y_T, x_T^2 + z_T^2 <= R^2 of Eq. (1)); then inclination alpha in 0.5 deg steps
//   up to 10 deg until free (Eq. (2)); reverse orientation by the sign of T's k
//   component: the primary orientation is the one of +-T with k >= 0 (Figures 10-11),
//   and its reverse is the alternative tried when the primary cannot be freed (Fig. 9b).
// Step 4 (§2.4): feed directions are grouped by orientation: reversing T is reversing
//   F (T = F x N), so a group is a run of consecutive cc-points on one slicing line fed
//   in one direction; cc-points with no free posture are non-machinable (Table 1).
//
// The seed leaves two things open; both are options here:
// - The rotation axis of the inclination. Eq. (2) rotates in the TCS X_T-Y_T plane, i.e.
//   about Z_T, the line from the tool centre through the cc-point (the normal): the
//   axis tilts within the tangent plane towards F and the flank stays tangent at the
//   cc-point (InclinationAxis::Normal, default). InclinationAxis::Feed instead rotates
//   the tool about the feed line through the cc-point, lifting its far end off the
//   surface (T tilts towards N).
// - Where the cc-point sits along the tool. The TCS of §2.3 has its origin at the tool
//   centre on the cc-point's level and counts y_T >= 0 along the axis, so the default
//   puts the tool's tip (bottom centre) level with the cc-point and the flute above it
//   (ccAxialPosition = 0); 0.5 centres the flute on the cc-point. The vertex test
//   looks at 0 <= y_T <= vertexTestLength (default the flute length L; the printed
//   test has no upper bound, a finite tool does).
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/gouge_check.h"
#include "analysis/triangle_mesh.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"

namespace scallop {

enum class InclinationAxis { Normal, Feed };
enum class PostureClass { FreeInitial, Inclined, Reversed, NonMachinable };
const char* toString(PostureClass c);
const char* toString(InclinationAxis a);

struct StrategyOptions {
  double sliceSpacing = 0;          // mm between slicing planes; <= 0: the flute length L
  char feedAxis = 'x';              // 'x': planes y = const, feed along +x; 'y': the converse
  double ccStep = 0;                // mm; > 0: pieces longer than this give several cc-points
  double ccAxialPosition = 0;       // where the cc-point sits along the flute, fraction of L
  double inclinationStepDeg = 0.5;  // §2.3
  double inclinationMaxDeg = 10;    // §2.3
  InclinationAxis inclinationAxis = InclinationAxis::Normal;
  bool inclineBothWays = false;   // also try -alpha at each step (after +alpha)
  double vertexTestLength = 0;    // mm along the axis for the vertex test; <= 0: L
  double vertexTolerance = 1e-9;  // mm: "inside" means closer to the axis than R - this
  double gougeTolerance = 1e-6;   // mm: an exact depth above this is a gouge
};

struct CcPoint {
  int plane = 0;          // slicing plane index
  int line = 0;           // connected piece of the slicing line within the plane
  Vec3 point;             // mm
  Vec3 normal;            // the facet's unit normal
  Vec3 feed;              // unit slicing-line direction, along +feed axis
  uint32_t triangle = 0;  // facet holding the cc-point
};

struct PostureResult {
  CcPoint cc;
  PostureClass verdict = PostureClass::NonMachinable;
  bool kNegative = false;     // F x N pointed down: the primary orientation is -(F x N)
  bool reversed = false;      // the posture uses the alternative (reverse) orientation
  double inclinationDeg = 0;  // alpha used (signed when inclineBothWays)
  Vec3 feedUsed;              // the group's feed: axis before inclination = feedUsed x N
  Pose pose;                  // the posture used; non-machinable: the initial posture
  bool vertexFree = false;    // the vertex test's verdict on `pose`
  double exactDepth = 0;      // mm, exact penetration of `pose` (gouge_check.h)
  int64_t deepestTriangle = -1;
  double initialExactDepth = 0;    // mm, exact penetration of the initial posture
  bool initialVertexFree = false;  // the vertex test's verdict on the initial posture
};

struct StrategySummary {
  size_t ccPoints = 0, planes = 0;
  size_t freeInitial = 0, inclined = 0, reversed = 0, nonMachinable = 0;
  size_t kNegative = 0;
  // §2.4 groups: runs of consecutive cc-points on one connected slicing line fed along
  // +feed axis (forward) or against it (backward), or non-machinable.
  size_t groupsForward = 0, groupsBackward = 0, groupsNonMachinable = 0;
  // Exact check of the accepted postures.
  size_t checkedPostures = 0;
  size_t gougingPostures = 0;          // exact depth > gougeTolerance
  size_t missedByVertexTest = 0;       // accepted by the vertex test and gouging
  double maxDepth = 0, meanDepth = 0;  // mm, over the gouging postures
  // The initial posture of every cc-point, both tests.
  size_t initialVertexInterference = 0, initialExactGouging = 0;
  double nonMachinablePct() const { return ccPoints ? 100.0 * nonMachinable / ccPoints : 0; }
  double machinablePct() const { return ccPoints ? 100.0 - nonMachinablePct() : 0; }
};

struct StrategyResult {
  std::vector<double> planes;           // slicing plane coordinates, mm
  std::vector<PostureResult> postures;  // ordered by plane, line, feed coordinate
  StrategySummary summary;
  // The accepted postures as a peripheral tool path: consecutive postures of a group
  // joined by linear moves (a one-posture group is a zero-length move), rapids between.
  ToolPath path;
};

// Pose of the cylinder tangent at `cc` (normal n, feed f, unit, orthogonal) with axis
// f x n before an inclination of `alphaDeg` about `axis` (see above).
Pose peripheralPose(const Vec3& cc, const Vec3& n, const Vec3& f, double alphaDeg,
                    InclinationAxis axis, const Cutter& cutter, double ccAxialPosition);

// Step 1 alone: the cc-points of every slicing plane.
std::vector<CcPoint> slicingCcPoints(const TriangleMesh& mesh, const StrategyOptions& options,
                                     double spacing, std::vector<double>* planes = nullptr);

// Steps 1-4 and the exact check. `cutter` must be flat. Parallel over cc-points; the
// result does not depend on the thread count.
StrategyResult runPeripheralStrategy(const MeshIndex& index, const Cutter& cutter,
                                     const StrategyOptions& options);

}  // namespace scallop
