#include "analysis/shadow_grid.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

struct Rect {
  double x0, y0, x1, y1;
};

// The rectangle of the (u, v) coordinates of the box's corners, grown by `slack`.
Rect shadowOf(const Box3& b, const Vec3& u, const Vec3& v, double slack) {
  Rect r{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y, c & 4 ? b.max.z : b.min.z};
    const double x = dot(p, u), y = dot(p, v);
    r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x);
    r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
  }
  return {r.x0 - slack, r.y0 - slack, r.x1 + slack, r.y1 + slack};
}

}  // namespace

bool ShadowGrid::build(const std::vector<Box3>& boxes, const Vec3& u, const Vec3& v, double slack,
                       double cellsPerBox) {
  std::vector<Rect> rects(boxes.size());
  Rect all{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (size_t k = 0; k < boxes.size(); ++k) {
    rects[k] = shadowOf(boxes[k], u, v, slack);
    all.x0 = std::min(all.x0, rects[k].x0), all.x1 = std::max(all.x1, rects[k].x1);
    all.y0 = std::min(all.y0, rects[k].y0), all.y1 = std::max(all.y1, rects[k].y1);
  }
  start_.assign(1, 0);
  ids_.clear();
  nx_ = ny_ = 0;
  if (boxes.empty()) return true;
  if (!(all.x1 - all.x0 < HUGE_VAL && all.y1 - all.y0 < HUGE_VAL)) return false;
  const double width = all.x1 - all.x0, height = all.y1 - all.y0;
  const double cells = std::min(double(1 << 22), std::max(1.0, cellsPerBox * double(boxes.size())));
  cell_ = std::max({std::sqrt(width * height / cells), width / 2048, height / 2048, 1e-9});
  x0_ = all.x0, y0_ = all.y0;
  nx_ = std::max<int64_t>(1, int64_t(std::ceil(width / cell_)));
  ny_ = std::max<int64_t>(1, int64_t(std::ceil(height / cell_)));
  // Two passes: count each cell's boxes, then place them, in box order.
  const auto cellRange = [&](const Rect& r, int64_t& i0, int64_t& j0, int64_t& i1, int64_t& j1) {
    i0 = std::clamp<int64_t>(int64_t(std::floor((r.x0 - x0_) / cell_)), 0, nx_ - 1);
    i1 = std::clamp<int64_t>(int64_t(std::floor((r.x1 - x0_) / cell_)), 0, nx_ - 1);
    j0 = std::clamp<int64_t>(int64_t(std::floor((r.y0 - y0_) / cell_)), 0, ny_ - 1);
    j1 = std::clamp<int64_t>(int64_t(std::floor((r.y1 - y0_) / cell_)), 0, ny_ - 1);
  };
  uint64_t entries = 0;
  for (const Rect& r : rects) {
    int64_t i0, j0, i1, j1;
    cellRange(r, i0, j0, i1, j1);
    entries += uint64_t(i1 - i0 + 1) * uint64_t(j1 - j0 + 1);
  }
  if (entries > std::max<uint64_t>(uint64_t(1) << 22, 32 * uint64_t(boxes.size()))) {
    nx_ = ny_ = 0;
    return false;
  }
  std::vector<uint32_t> count(size_t(nx_ * ny_) + 1, 0);
  for (const Rect& r : rects) {
    int64_t i0, j0, i1, j1;
    cellRange(r, i0, j0, i1, j1);
    for (int64_t j = j0; j <= j1; ++j)
      for (int64_t i = i0; i <= i1; ++i) ++count[size_t(j * nx_ + i) + 1];
  }
  start_.assign(count.size(), 0);
  for (size_t c = 1; c < count.size(); ++c) start_[c] = start_[c - 1] + count[c];
  ids_.resize(start_.back());
  std::vector<uint32_t> next(start_.begin(), start_.end() - 1);
  for (size_t k = 0; k < rects.size(); ++k) {
    int64_t i0, j0, i1, j1;
    cellRange(rects[k], i0, j0, i1, j1);
    for (int64_t j = j0; j <= j1; ++j)
      for (int64_t i = i0; i <= i1; ++i) ids_[next[size_t(j * nx_ + i)]++] = uint32_t(k);
  }
  return true;
}

const uint32_t* ShadowGrid::boxesAt(double x, double y, size_t& count) const {
  count = 0;
  if (nx_ == 0) return nullptr;
  const double fi = std::floor((x - x0_) / cell_), fj = std::floor((y - y0_) / cell_);
  // Outside the rectangles' union (or NaN): no box.
  if (!(fi >= 0 && fi < double(nx_) && fj >= 0 && fj < double(ny_))) return nullptr;
  const size_t c = size_t(int64_t(fj) * nx_ + int64_t(fi));
  count = start_[c + 1] - start_[c];
  return ids_.data() + start_[c];
}

}  // namespace scallop
