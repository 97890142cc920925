// Micro-benchmarks of the exact kernel (SweptSegment::lowestPoint, cutterLowestPoint),
// of the scene build and of casting, for `scallop_microbench` (Google Benchmark; not
// part of ctest). Each kernel benchmark cycles through 1024 query points so that the
// branch predictor and the caches see a realistic mix, and reports items/s = queries/s.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "raycast/swept_scene.h"
#include "raycast/zmap_caster.h"
#include "sweep/raster.h"
#include "sweep/swept_segment.h"
#include "sweep/tool_path_sweep.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

constexpr int kQueries = 1024;

Cutter cutterOf(int type) {
  switch (type) {
    case 0:
      return Cutter::make(CutterType::Ball, 3);
    case 1:
      return Cutter::make(CutterType::Flat, 3);
    default:
      return Cutter::make(CutterType::Bull, 3, 1);
  }
}
const char* typeName(int type) {
  return type == 0 ? "ball" : type == 1 ? "flat" : "bull";
}

// Axis: vertical, or the B1 lead of 5 deg plus a 3 deg tilt (a general 5-axis pose).
Vec3 axisOf(bool tilted) {
  return tilted ? leadTiltAxis({1, 0, 0}, 5, 3) : Vec3{0, 0, 1};
}

// Query points over the footprint of a 10 mm move along x from the origin. "swept":
// x inside the move, so most answers come from the envelope; "endpoint": x behind the
// start, so every answer is the stationary cutter at t = 0 (Newton's method).
std::vector<Vec3> queries(bool endpoint) {
  std::vector<Vec3> q(kQueries);
  for (int k = 0; k < kQueries; ++k) {
    const double y = -2.7 + 5.4 * ((k * 37) % kQueries) / kQueries;
    const double x = endpoint ? -0.05 - 0.5 * ((k * 11) % kQueries) / kQueries
                              : 1 + 8.0 * ((k * 53) % kQueries) / kQueries;
    q[size_t(k)] = {x, y, 0};
  }
  return q;
}

void BM_LowestPoint(benchmark::State& state) {
  const int type = int(state.range(0));
  const bool tilted = state.range(1) != 0, endpoint = state.range(2) != 0;
  const SweptSegment seg(cutterOf(type), {0, 0, 0}, {10, 0, 0.2}, axisOf(tilted));
  const std::vector<Vec3> q = queries(endpoint);
  size_t k = 0;
  for (auto _ : state) {
    const Vec3& p = q[k++ & (kQueries - 1)];
    benchmark::DoNotOptimize(seg.lowestPoint(p.x, p.y));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(std::string(typeName(type)) + (tilted ? " tilted" : " vertical") +
                 (endpoint ? " endpoint" : " swept"));
}
BENCHMARK(BM_LowestPoint)->ArgsProduct({{0, 1, 2}, {0, 1}, {0, 1}});

void BM_CutterLowestPoint(benchmark::State& state) {
  const int type = int(state.range(0));
  const bool tilted = state.range(1) != 0;
  const Cutter cutter = cutterOf(type);
  const Vec3 axis = axisOf(tilted);
  const std::vector<Vec3> q = queries(true);
  size_t k = 0;
  for (auto _ : state) {
    const Vec3& p = q[k++ & (kQueries - 1)];
    benchmark::DoNotOptimize(cutterLowestPoint(cutter, axis, p.x + 0.3, p.y));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(std::string(typeName(type)) + (tilted ? " tilted" : " vertical"));
}
BENCHMARK(BM_CutterLowestPoint)->ArgsProduct({{0, 1, 2}, {0, 1}});

// B1-like (one move per pass), B2-like (0.05 mm moves) and B3-like paths over a 4 x 4 mm
// stock, by the benchmark's argument 1, 2 or 3: the case, its segments, the scene options.
struct BenchScene {
  const char* name;
  BenchCase bench;
  std::vector<SweptMove> segments;
  SceneOptions options;
};
BenchScene benchScene(const benchmark::State& state) {
  BenchScene s;
  s.name = state.range(0) == 1 ? "B1" : state.range(0) == 2 ? "B2" : "B3";
  BenchCaseOptions options;
  options.quick = true;
  options.area = 4;
  s.bench = makeBenchCase(s.name, options);
  s.segments = sweepToolPath(s.bench.cutter, s.bench.path);
  s.options.stockTop = s.bench.stock.max.z;
  return s;
}

void BM_SceneBuild(benchmark::State& state) {
  const BenchScene s = benchScene(state);
  const char* name = s.name;
  const std::vector<SweptMove>& segments = s.segments;
  for (auto _ : state) {
    const SweptScene scene(segments, s.options);
    benchmark::DoNotOptimize(scene.stats().tiles);
  }
  state.SetItemsProcessed(state.iterations() * int64_t(segments.size()));
  state.SetLabel(std::string(name) + "-like, 4 x 4 mm, " + std::to_string(segments.size()) +
                 " segments");
}
BENCHMARK(BM_SceneBuild)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

// Casting only (the scene is built once): cells/s of the exact path, 10 um grid.
void BM_Cast(benchmark::State& state) {
  const BenchScene s = benchScene(state);
  const char* name = s.name;
  const BenchCase& b = s.bench;
  const SweptScene scene(s.segments, s.options);
  uint64_t evaluations = 0;
  for (auto _ : state) {
    ZMap map(b.grid, b.stock.max.z);
    evaluations += castZMap(scene, map).exactEvaluations;
  }
  state.SetItemsProcessed(state.iterations() * b.grid.cells());
  state.counters["evals_per_cell"] =
      double(evaluations) / double(state.iterations() * b.grid.cells());
  state.SetLabel(std::string(name) + "-like, 4 x 4 mm, cells/s");
}
BENCHMARK(BM_Cast)->DenseRange(1, 3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace scallop
