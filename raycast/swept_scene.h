// SweptScene: an Embree scene over the swept solids of a tool path, used to find, for
// each vertical line, the few swept segments whose exact height can be the lowest.
//
// Culling, not approximation: every segment's footprint is cut into xy tiles, and each
// tile becomes one Embree user primitive whose box starts at a *proven* lower bound of
// the segment's heights over the tile (from supporting planes of the convex swept
// solid). A ray cast upwards from below meets the boxes in order of those bounds; each
// exact evaluation lowers the ray's far end, so boxes that start above the lowest
// height found so far are never entered. Heights themselves are always computed in
// double by SweptSegment::lowestPoint.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sweep/swept_segment.h"

namespace scallop {

struct SceneOptions {
  double tileSize = 0;   // xy tile side, mm; <= 0 picks cutter radius / 8
  double stockTop = 0;   // heights above this never matter (the ray stops there), mm
};

struct SceneStats {
  size_t segments = 0;
  size_t tiles = 0;            // Embree primitives
  size_t boundEvaluations = 0; // exact evaluations spent on building the bounds
  double buildSeconds = 0;
};

class SweptScene {
 public:
  SweptScene(std::vector<SweptSegment> segments, const SceneOptions& options);
  ~SweptScene();
  SweptScene(const SweptScene&) = delete;
  SweptScene& operator=(const SweptScene&) = delete;

  // The lowest height at (x, y) over all segments, or `ceiling` if none is lower.
  // `evaluations` is incremented by the number of exact evaluations made.
  double lowestHeight(double x, double y, double ceiling, uint64_t& evaluations) const;

  const std::vector<SweptSegment>& segments() const;
  const SceneStats& stats() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace scallop
