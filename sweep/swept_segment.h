// SweptSegment: the solid swept by a cutter moving along one straight segment with a
// fixed axis, and its exact lowest point on a vertical line.
//
// The swept solid C = K (+) [0, d] is convex (K is), so its lower boundary is a convex
// height function F(x, y). F is evaluated exactly in double: see swept_segment.cpp.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

#include "base/vec3.h"
#include "sweep/cutter.h"

namespace scallop {

// The lowest point of a swept solid on one vertical line.
struct LowestPoint {
  bool hit = false;  // false: the vertical line misses the solid
  double z = 0;      // mm, valid when hit
  // Outward normal of the solid at that point (unit). When normal.z < 0 the plane
  // through (x, y, z) with this normal supports the solid from below, so it bounds
  // F from below everywhere: the scene uses it for conservative culling.
  Vec3 normal;
  // The pose parameter in [0, 1] of a move at which the cutter reaches that point (set
  // by turning moves, SweptMove; 0 otherwise).
  double t = 0;
};

class SweptSegment;

// The plane section's support point (step 3 in swept_segment.cpp) for one offset of
// the section plane; heights along a line parallel to the move share it.
struct SweptSection {
  bool hit = false;  // false: the section plane misses the cutter
  Vec3 point;        // support point, tool frame (tip at the origin), mm
  Vec3 normal;       // outward unit normal there
};

// A one-entry memo of the last section a caller needed from one segment. Keyed by the
// segment and the exact bits of the offset, so results are identical with or without it.
struct SectionMemo {
  const SweptSegment* owner = nullptr;
  double offset = 0;
  SweptSection section;
};

class SweptSegment {
 public:
  using Section = SweptSection;

  // `axis` must be a unit vector; `start`/`end` are tip positions, mm.
  SweptSegment(const Cutter& cutter, const Vec3& start, const Vec3& end, const Vec3& axis);
  // A copy takes the section nodes that are built already.
  SweptSegment(const SweptSegment& other);
  SweptSegment& operator=(const SweptSegment&) = delete;

  // Exact lowest point of the swept solid on the vertical line through (x, y).
  LowestPoint lowestPoint(double x, double y) const;
  // The same, reusing `memo` (which it updates) when the section plane is the same.
  // A point at or above `cutoff` may be reported as a miss: callers that only want
  // heights below their current best pass it and skip work that cannot matter.
  LowestPoint lowestPoint(double x, double y, SectionMemo* memo, double cutoff = HUGE_VAL) const;

  // Tight axis-aligned bounds of the swept solid.
  Box3 bounds() const;

  // Support function of the swept solid: max of dot(dir, p) over the solid. For any
  // dir with dir.z < 0 the plane dot(dir, p) = support(dir) bounds the heights from
  // below everywhere, which is what the scene's culling bounds are made of.
  double support(const Vec3& dir) const;

  const Cutter& cutter() const { return cutter_; }
  const Vec3& start() const { return start_; }
  const Vec3& end() const { return end_; }
  const Vec3& axis() const { return axis_; }

 private:
  Section section(double offset) const;
  // The safeguarded Newton search of step 3 in [th1, th2] from th; `root` gets the
  // parameter of the answer when not null.
  Section search(double offset, double th1, Vec3 x1, double th2, Vec3 x2, double th,
                 double* root) const;

  Cutter cutter_;
  Vec3 start_, end_, axis_, delta_;
  double zMin_ = 0;  // the stationary cutter's lowest z, tip at the origin, mm
  // Step 1's frame: horizontal length w_ of the move, its direction uHat_, the section
  // plane normal m_, slope sigma_, the search direction n_, and K's extremes along m_.
  double w_ = 0, sigma_ = 0;
  Vec3 uHat_, m_, n_, lowM_, highM_;
  // Section roots (parameter and support point) at evenly spaced offsets across K.
  static constexpr int kSectionNodes = 17;
  struct SectionNode {
    double t = 0;
    Vec3 point;
    double dcdt = 0;  // slope of the offset along the parameter there (0: unknown)
  };
  // A node is built on the first section() that needs it, not with the segment: the 15
  // searches were half of the scene build of a million short moves (B9), and a
  // line of cells needs two neighbouring nodes (a B9 cell's segments, 2 to 4 of 15).
  // A node depends on the segment and its index alone, so every thread computes the
  // same bits; the first to claim it publishes it, and a thread that finds it claimed
  // but not ready uses its own copy. Bit k of nodesReady_: nodes_[k] may be read.
  SectionNode sectionNode(int k) const {
    return (nodesReady_.load(std::memory_order_acquire) >> k) & 1 ? nodes_[size_t(k)]
                                                                  : buildSectionNode(k);
  }
  SectionNode buildSectionNode(int k) const;
  mutable std::atomic<uint32_t> nodesReady_{0}, nodesClaimed_{0};
  mutable std::array<SectionNode, kSectionNodes> nodes_{};
};

// Support point of the stationary cutter (tip at origin, unit axis `axis`) in
// direction `dir` (need not be unit): a point of K maximising dot(dir, p).
Vec3 cutterSupport(const Cutter& cutter, const Vec3& axis, const Vec3& dir);

// Exact lowest point of the stationary cutter (tip at origin) on the vertical line
// through (x, y). Exposed for tests and for the stamping baseline. `zBelow`, if given,
// must be a proven lower bound of the answer; the search then starts there.
LowestPoint cutterLowestPoint(const Cutter& cutter, const Vec3& axis, double x, double y,
                              double zBelow = -HUGE_VAL);

}  // namespace scallop
