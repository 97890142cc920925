// SweptSegment's section nodes are built on first use, one at a time, by whichever
// thread needs them first (swept_segment.h). A height must not depend on that: the same
// bits in any order of evaluation, from any number of threads, and in a copy taken
// before, while or after the nodes are built.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cstring>
#include <random>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/swept_segment.h"

namespace scallop {
namespace {

// The heights (and misses, as NaN) of `seg` at `points`, in the order given by `order`.
std::vector<double> heightsAt(const SweptSegment& seg, const std::vector<Vec3>& points,
                              const std::vector<size_t>& order) {
  std::vector<double> z(points.size());
  for (size_t i : order) {
    const LowestPoint lp = seg.lowestPoint(points[i].x, points[i].y);
    z[i] = lp.hit ? lp.z : std::nan("");
  }
  return z;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(SectionNodes, HeightsDoNotDependOnWhichNodesWereBuiltFirst) {
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Cutter cutters[] = {Cutter::make(CutterType::Ball, 1), Cutter::make(CutterType::Bull, 3, 1),
                            Cutter::make(CutterType::Flat, 2)};
  for (int trial = 0; trial < 12; ++trial) {
    const Cutter& cutter = cutters[trial % 3];
    const Vec3 start{unit(rng), unit(rng), unit(rng)};
    const Vec3 end = start + Vec3{2 * unit(rng), 2 * unit(rng), 0.5 * unit(rng)};
    const Vec3 axis = normalize(Vec3{0.3 * unit(rng), 0.3 * unit(rng), 1});
    std::vector<Vec3> points;
    for (int i = 0; i < 400; ++i) points.push_back(start + Vec3{4 * unit(rng), 4 * unit(rng), 0});
    std::vector<size_t> forward(points.size()), backward(points.size());
    for (size_t i = 0; i < points.size(); ++i) forward[i] = i, backward[i] = points.size() - 1 - i;

    const SweptSegment first(cutter, start, end, axis);
    const SweptSegment untouched(first);  // copied before any node is built
    const std::vector<double> reference = heightsAt(first, points, forward);
    EXPECT_TRUE(sameBits(heightsAt(untouched, points, backward), reference)) << trial;
    const SweptSegment built(first);  // copied with its nodes
    EXPECT_TRUE(sameBits(heightsAt(built, points, backward), reference)) << trial;

    // Every thread racing for the same nodes of a fresh segment.
    const SweptSegment shared(cutter, start, end, axis);
    std::vector<double> parallel(points.size());
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
      const LowestPoint lp = shared.lowestPoint(points[i].x, points[i].y);
      parallel[i] = lp.hit ? lp.z : std::nan("");
    });
    EXPECT_TRUE(sameBits(parallel, reference)) << trial;
  }
}

}  // namespace
}  // namespace scallop
