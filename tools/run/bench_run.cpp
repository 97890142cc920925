#include "tools/run/bench_run.h"

#include <fmt/core.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <sys/resource.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>
#include <thread>
#include <utility>

#include "base/internal_error.h"
#include "raycast/simulation.h"
#include "raycast/stamp_caster.h"
#include "tools/run/bench_cases.h"
#include "tools/run/read_bench.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"

namespace scallop {

using nlohmann::json;

namespace {

// Peak resident memory. Linux lets a process reset its own high-water mark (write 5
// to /proc/self/clear_refs), which makes the peak per case; elsewhere ru_maxrss is the
// process-wide peak so far, and cases are run from the smallest grid to the largest.
bool resetPeakRss() {
  std::ofstream f("/proc/self/clear_refs");
  return bool(f << "5") && bool(f.flush());
}
double peakRssMb() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // kB on Linux
}

CellProgress openStage(const BenchSettings& s, const std::string& label) {
  return s.openStage ? s.openStage(label) : CellProgress();
}

constexpr int kRuns = 2;  // timed runs per configuration; the fastest counts

struct ExactRun {
  double seconds = 0;  // simulate(): sweep + scene build + cast
  SceneStats scene;
  CastStats cast;
  uint64_t hash = 0;
};

// One timed simulate() in an arena of `threads` workers: exactly the `simulate` path,
// with the case's cutting model or (`envelope`) the envelope's.
ExactRun runExact(const BenchSettings& s, const BenchCase& b, int threads, bool envelope = false) {
  ExactRun r;
  CellProgress progress =
      openStage(s, fmt::format("{}{} ({} thread{})", b.name, envelope ? " envelope" : "", threads,
                               threads == 1 ? "" : "s"));
  tbb::task_arena arena(threads);
  arena.execute([&] {
    SimulationOptions options;
    if (!envelope) options.cutting = b.cutting;
    options.cast.progress = progress;
    const auto t0 = Clock::now();
    const SimulationResult sim = simulate(b.cutter, b.path, b.stock, b.grid, options);
    r.seconds = secondsSince(t0);
    r.scene = sim.scene;
    r.cast = sim.cast;
    r.hash = heightsHash(sim.map);
  });
  // The next run starts from a heap without this run's freed blocks, so that the case's
  // peak is one run's own. Without it the peak depended on where the allocator put a
  // run's blocks among the last run's freed ones: B9 --area 31's peak over the four runs
  // moved by 23 MB (full size: 220 MB) with the order of a few small allocations in the
  // sweep, for the same bytes in use at every step and the same peak in the first run.
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  return r;
}

struct StampComparison {
  GridSpec window;
  double stepMm = 0, maxErrorMm = 0, minDifferenceMm = 0;
  double exactSeconds = 0, stampSeconds = 0;
  double stepFactor = 1;  // step / stampStepFor's estimate
  uint64_t stampEvaluations = 0, stamps = 0;
  double exactEvalsPerCell = 0;
};

// Exact and stamped heights of a small window, with the same segments (those whose
// box reaches the window: the others cannot change it). The stamp step starts at
// stampStepFor's estimate and is doubled or halved to the largest power-of-two multiple
// whose stamped map is within 1e-4 mm of the exact one: equal accuracy.
StampComparison compareWithStamping(const BenchSettings& s, const BenchCase& b, double side,
                                    int threads) {
  StampComparison c;
  c.window = stampWindow(b, side);
  const GridSpec& w = c.window;
  const double wx1 = w.originX + w.nx * w.spacing, wy1 = w.originY + w.ny * w.spacing;
  std::vector<SweptMove> segments;
  for (const SweptMove& s : sweepToolPath(b.cutter, b.path)) {
    const Box3 box = s.bounds();
    if (box.max.x >= w.originX && box.min.x <= wx1 && box.max.y >= w.originY && box.min.y <= wy1)
      segments.push_back(s);
  }
  constexpr double kTolerance = 1e-4;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    // Exactly as simulate() builds and casts it (region queries included); both sides'
    // times are the best of kRuns runs, like the cases'.
    ZMap exact(w, b.stock.max.z);
    for (int run = 0; run < kRuns; ++run) {
      const auto t0 = Clock::now();
      const SweptScene scene(segments, sceneOptionsFor(b.stock, w.spacing, SimulationOptions()));
      ZMap heights(w, b.stock.max.z);
      const CastStats cast = castZMap(scene, heights);
      const double seconds = secondsSince(t0);
      if (run == 0 || seconds < c.exactSeconds) c.exactSeconds = seconds;
      c.exactEvalsPerCell = cast.evaluationsPerCell();
      exact = std::move(heights);
    }

    // The largest step derived * 2^k (k <= 3) that stays within the tolerance: the
    // derived step has a safety margin, and the baseline deserves its best showing.
    StampOptions options;
    options.tolerance = kTolerance;
    double derived = 0;
    bool passedBefore = false;
    StampOptions chosen;
    auto stampWith = [&](StampOptions opts, ZMap& stamped) {
      opts.progress = openStage(s, fmt::format("{} stamping", b.name));
      return stampZMap(segments, stamped, opts);
    };
    for (int k = 0; k < 12; ++k) {
      ZMap stamped(w, b.stock.max.z);
      const StampStats stats = stampWith(options, stamped);
      if (derived == 0) derived = stats.minStep;
      double maxError = -HUGE_VAL, minDifference = HUGE_VAL;
      for (size_t i = 0; i < exact.heights().size(); ++i) {
        const double d = stamped.heights()[i] - exact.heights()[i];
        maxError = std::max(maxError, d);
        minDifference = std::min(minDifference, d);
      }
      const bool passed = maxError <= kTolerance;
      if (passed || !passedBefore) {  // keep the best passing run (or the latest failure)
        chosen = options;
        c.stampSeconds = stats.seconds;
        c.stepMm = stats.minStep;
        c.stampEvaluations = stats.exactEvaluations;
        c.stamps = stats.positions;
        c.maxErrorMm = maxError, c.minDifferenceMm = minDifference;
        c.stepFactor = stats.minStep / derived;
      }
      if (passed && c.stepFactor < 8) {
        passedBefore = true;
        options.step = 2 * stats.minStep;
      } else if (!passed && !passedBefore) {
        options.step = 0.5 * stats.minStep;
      } else {
        break;
      }
    }
    // The chosen step once more, for its best of kRuns.
    for (int run = 1; run < kRuns; ++run) {
      ZMap stamped(w, b.stock.max.z);
      c.stampSeconds = std::min(c.stampSeconds, stampWith(chosen, stamped).seconds);
    }
  });
  return c;
}

struct CaseResult {
  BenchCase bench;
  ExactRun timed, single;
  ExactRun envelope;  // a teeth case's grid and path with the envelope (B5: B1's raster)
  int threads = 0;
  double peakRssMb = 0;
};

json caseJson(const CaseResult& r) {
  const ExactRun& t = r.timed;
  json j = {
      {"name", r.bench.name},
      {"description", r.bench.description},
      {"cells", r.bench.grid.cells()},
      {"spacing_mm", r.bench.grid.spacing},
      {"moves", r.bench.path.cuttingMoves()},
      {"segments", t.scene.segments},
      {"culling_tiles", t.scene.tiles},
      {"scene_bytes", t.scene.bytes()},
      {"scene_bytes_detail",
       {{"moves", t.scene.moveBytes}, {"tiles", t.scene.tileBytes}, {"grid", t.scene.gridBytes}}},
      {"evals_per_cell", t.cast.evaluationsPerCell()},
      {"seconds", t.seconds},
      {"scene_seconds", t.scene.buildSeconds},
      {"cast_seconds", t.cast.seconds},
      {"mcells_per_s", double(t.cast.cells) / t.seconds / 1e6},
      {"peak_rss_mb", r.peakRssMb},
      {"threads", r.threads},
      {"seconds_1_thread", r.single.seconds},
      {"heights_hash", fmt::format("{:016x}", t.hash)}};
  // The scene's figures: build in moves a second (the program's cutting moves), and
  // bytes a move, the scene's own accounting and the peak beyond the map's heights.
  const double moves = double(std::max<size_t>(1, r.bench.path.cuttingMoves()));
  const double mapBytes = 8.0 * double(r.bench.grid.cells());
  j["scene_moves_per_s"] = moves / t.scene.buildSeconds;
  j["scene_bytes_per_move"] = double(t.scene.bytes()) / moves;
  j["peak_beyond_map_bytes_per_move"] = (r.peakRssMb * 1048576.0 - mapBytes) / moves;
  j["scene_over_cast"] = t.scene.buildSeconds / t.cast.seconds;
  // Only a 2-thread run has a 2-vs-1 speed-up; other counts report theirs separately.
  j["speedup_2v1"] = r.threads == 2 ? json(r.single.seconds / t.seconds) : json(nullptr);
  if (r.threads != 2 && r.threads != 1) j["speedup_vs_1"] = r.single.seconds / t.seconds;
  j["cutting"] = r.bench.cutting.teeth() ? "teeth" : "envelope";
  if (r.bench.cutting.teeth()) {
    j["envelope_seconds"] = r.envelope.seconds;
    j["teeth_over_envelope"] = t.seconds / r.envelope.seconds;
  }
  return j;
}

json stampJson(const StampComparison& c) {
  return {{"window_mm", c.window.nx * c.window.spacing},
          {"cells", c.window.cells()},
          {"step_mm", c.stepMm},
          {"step_over_estimate", c.stepFactor},
          {"stamps", c.stamps},
          {"max_error_mm", c.maxErrorMm},
          {"min_difference_mm", c.minDifferenceMm},
          {"stamp_evals_per_cell", double(c.stampEvaluations) / double(c.window.cells())},
          {"exact_evals_per_cell", c.exactEvalsPerCell},
          {"stamp_seconds", c.stampSeconds},
          {"exact_seconds", c.exactSeconds}};
}

}  // namespace

BenchResult runBench(const BenchSettings& args) {
  std::vector<std::string> names = args.cases.empty() ? defaultBenchCaseNames() : args.cases;
  // B11 reads a program, simulates nothing: it runs apart from the cases (read_bench.h).
  const bool reading =
      args.cases.empty() || std::find(names.begin(), names.end(), "B11") != names.end();
  names.erase(std::remove(names.begin(), names.end(), "B11"), names.end());
  BenchCaseOptions caseOptions;
  caseOptions.quick = args.quick;
  caseOptions.area = args.area;
  const int threads = args.threads > 0 ? args.threads : 2;

  // The cases are reported in the standard order whatever the order asked; an unknown name is
  // makeBenchCase's InputError ("--case"), which the CLI's own check never lets through.
  const std::vector<std::string>& known = benchCaseNames();
  for (const std::string& name : names)
    if (std::find(known.begin(), known.end(), name) == known.end())
      makeBenchCase(name, caseOptions);
  std::vector<BenchCase> cases;
  for (const std::string& name : known)
    if (std::find(names.begin(), names.end(), name) != names.end())
      cases.push_back(makeBenchCase(name, caseOptions));

  // Stamping baseline first (small windows), then the cases from the smallest grid to
  // the largest, so that a process-wide peak would still be each case's own.
  json stamp = json::object(), ratio = json::object();
  const double side = args.stampWindow > 0 ? args.stampWindow : (args.quick ? 1.0 : 0.5);
  if (args.stamp)
    for (const BenchCase& b : cases) {
      if (b.name != "B1" && b.name != "B3") continue;  // the issues compare B1 and B3
      const StampComparison c = compareWithStamping(args, b, side, threads);
      stamp[b.name] = stampJson(c);
      ratio[b.name] = c.stampSeconds / c.exactSeconds;
    }

  std::vector<size_t> order(cases.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return cases[a].grid.cells() < cases[b].grid.cells();
  });
  std::vector<CaseResult> results(cases.size());
  bool perCasePeak = true;
  for (size_t k : order) {
    CaseResult& r = results[k];
    r.bench = cases[k];
    r.threads = threads;
    perCasePeak = resetPeakRss() && perCasePeak;
    // Each timing is the best of kRuns runs, alternating 1 and N threads: on these VMs
    // memory the host has taken back can cost minutes on its first touch (B1's 3.2 GB
    // map once took 124 s instead of 8 s), which a single run would charge to whichever
    // configuration happened to come first.
    for (int run = 0; run < kRuns; ++run) {
      const ExactRun single = runExact(args, r.bench, 1);
      const ExactRun timed = threads == 1 ? single : runExact(args, r.bench, threads);
      if (single.hash != timed.hash || (run > 0 && single.hash != r.single.hash))
        throw InternalError(r.bench.name + ": heights differ between 1 and " +
                            std::to_string(threads) + " threads");
      if (run == 0 || single.seconds < r.single.seconds) r.single = single;
      if (run == 0 || timed.seconds < r.timed.seconds) r.timed = timed;
      if (r.bench.cutting.teeth()) {
        const ExactRun envelope = runExact(args, r.bench, threads, true);
        if (run == 0 || envelope.seconds < r.envelope.seconds) r.envelope = envelope;
      }
    }
    r.peakRssMb = peakRssMb();
  }

  json doc = newReport(threads);
  doc["cases"] = json::array();
  for (const CaseResult& r : results) doc["cases"].push_back(caseJson(r));
  if (reading) {
    const ReadBenchResult read = runReadBench(args.quick, args.area);
    doc["reading"] = {{"name", "B11"},
                      {"width_mm", read.width},
                      {"bytes", read.bytes},
                      {"moves", read.moves},
                      {"seconds", read.seconds},
                      {"mb_per_s", read.bytes / 1e6 / read.seconds},
                      {"moves_per_s", double(read.moves) / read.seconds}};
  }
  doc["stamp_ratio"] = ratio;
  doc["stamp"] = stamp;
  doc["quick"] = args.quick;
  doc["area_mm"] = args.area > 0 ? args.area : 20.0;
  doc["hardware_threads"] = std::thread::hardware_concurrency();
  doc["peak_rss_scope"] = perCasePeak ? "per case" : "process-wide high-water mark";
  doc["stamp_ratio_meaning"] = "stamping seconds / exact seconds on the same window at <= 1e-4 mm";
  return {doc};
}

}  // namespace scallop
