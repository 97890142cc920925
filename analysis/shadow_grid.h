// ShadowGrid: for lines that share one direction n, which boxes a line can meet. Each
// box's shadow along n on the plane spanned by u and v (unit, across n) lies in the
// rectangle of its corners' (u, v) coordinates; a 2-D grid over those rectangles lists,
// per cell, the boxes whose rectangle (grown by a slack) overlaps it. A line through a
// point p meets a box only if (p.u, p.v) is in its rectangle, so a cell's list holds
// every box its lines can meet (and more: the caller applies its own exact test).
//
// The normal deviation's candidate search for the many vertices of a flat face
// (analysis/normal_deviation.cpp): one build per normal instead of a BVH ray a vertex.
#pragma once

#include <cstdint>
#include <vector>

#include "base/vec3.h"

namespace scallop {

class ShadowGrid {
 public:
  // About `cellsPerBox` cells a box over the rectangles' union (at most 2^22 cells).
  // False (and an empty grid) when the lists would hold more than max(2^22, 32 a box)
  // entries (long boxes across the grid's axes): the caller then searches otherwise.
  bool build(const std::vector<Box3>& boxes, const Vec3& u, const Vec3& v, double slack,
             double cellsPerBox = 16);

  // The boxes (indices, ascending) whose rectangle may hold (x, y) = (p.u, p.v):
  // [first, first + count).
  const uint32_t* boxesAt(double x, double y, size_t& count) const;

 private:
  double x0_ = 0, y0_ = 0, cell_ = 1;  // the grid's corner and cell side, mm
  int64_t nx_ = 0, ny_ = 0;
  std::vector<uint32_t> start_;  // cell c's boxes: ids_[start_[c], start_[c + 1])
  std::vector<uint32_t> ids_;
};

}  // namespace scallop
