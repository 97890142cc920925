// report.json "feed_marks" of a run with the teeth cutting model (docs/teeth.md): the
// heights along the pass centre line nearest the map centre, their peak-to-valley and
// the marks' mean spacing (analysis/feed_marks.h), beside the closed form for a raster
// (analysis/feed_mark_formula.h).
//
// The line: of the cutting moves whose xy segment has a length, the one passing
// nearest the map's centre, extended over the moves before and after it that continue
// it (collinear in xy, same direction, same tool: a raster pass cut into segments),
// less one cutter radius at both ends (where the cutter enters and leaves), clipped to
// the span of the cell centres. Samples every grid spacing from its start; each height
// is the bilinear interpolation of the four surrounding cell centres, as
// `scallop export --profile` samples (analysis/profile_metrology.h).
//
// "passes": every straight cutting run of the path (the moves that continue one another
// as above; arcs and rapids end a run), the first 64 listed, each with its moves and its
// line (as above, the same trimming and clipping) and the same measurement, or the
// reason it has none (shorter than two cutter radii, does not cross the map): a pass
// that misses the map is reported as such, not refused. "pass_count" and
// "passes_crossing_the_map" count them all.
//
// The plan (the line, the passes, the prediction) depends only on the job and the grid, so a run
// in bands carries it in its description and every band gives the cells it holds.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

struct Job;

// {"line": {...}, "predicted": {...}} (or "reason" / "predicted_reason" saying why
// not) for a teeth job; null for an envelope job.
nlohmann::json feedMarkPlan(const Job& job, const GridSpec& grid);

// Gathers the heights a plan's line needs from the whole map or from bands of it, in
// any order, and measures them.
class FeedMarkSampler {
 public:
  FeedMarkSampler(const nlohmann::json& plan, const GridSpec& grid);
  void add(const ZMap& map);  // a map or band with `grid`'s origin and spacing
  // The plan with the measurement: "peak_to_valley_um", "mean_spacing_mm", "valleys".
  nlohmann::json report() const;

 private:
  nlohmann::json plan_;
  GridSpec grid_;
  struct Sample {
    int64_t i0, j0, i1, j1;
    double u, v;
  };
  struct Line {
    std::vector<Sample> samples;
    std::vector<double> cells;  // 4 per sample: (i0,j0) (i1,j0) (i0,j1) (i1,j1)
    double stepMm = 0;
  };
  void addLine(const nlohmann::json& line);
  static void measure(const Line& line, nlohmann::json& out);
  std::vector<Line> lines_;  // the plan's "line", then each pass's that has one
};

// The "feed_marks" section of an in-memory run: null for an envelope job.
nlohmann::json feedMarksReport(const Job& job, const ZMap& map);

}  // namespace scallop
