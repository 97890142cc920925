// MoveLineIndex: which of a set of boxes a segment of a line in any direction can meet,
// for the normal deviation's candidate search (analysis/normal_deviation.h): an Embree
// BVH of user boxes, one per cutting move (its proven box), and a ray along the line.
//
// Conservative, never exact: the boxes are grown by `slack` mm before Embree sees them,
// so that the ray's float rounding cannot lose a box that the segment meets; the caller
// applies its own exact test to what is returned.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "base/vec3.h"

namespace scallop {

class MoveLineIndex {
 public:
  // `slack` (mm) must exceed the float rounding of every segment asked about: a few
  // 1e-7 of the largest coordinate of the points and boxes involved.
  MoveLineIndex(const std::vector<Box3>& boxes, double slack);
  ~MoveLineIndex();
  MoveLineIndex(const MoveLineIndex&) = delete;
  MoveLineIndex& operator=(const MoveLineIndex&) = delete;

  // Replaces `ids` with the indices (ascending) of the boxes that may meet the segment
  // p + w n, w in [w0, w1] (n unit; w0 <= w1 finite): every box the segment meets is
  // among them.
  void boxesMeeting(const Vec3& p, const Vec3& n, double w0, double w1,
                    std::vector<uint32_t>& ids) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scallop
