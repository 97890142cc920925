#include "tools/run/feed_mark_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "analysis/feed_mark_formula.h"
#include "analysis/feed_marks.h"
#include "analysis/pass_section.h"
#include "analysis/profile_metrology.h"
#include "base/constants.h"
#include "tools/io/job.h"

namespace scallop {

using nlohmann::json;

namespace {

constexpr const char* kSampling =
    "every grid spacing along the line, each height the bilinear interpolation of the four "
    "surrounding cell centres";
std::string spacingMethod() {
  return fmt::format(
      "valleys: turning points with a hysteresis of {:g}% of the peak-to-valley, each refined "
      "by the parabola through its sample and its two neighbours; spacing = (last - first) / "
      "(valleys - 1)",
      100 * kFeedMarkHysteresis);
}

struct Xy {
  double x, y;
};

// Whether move b, right after a, continues a's straight line in xy in the same sense
// (an arc, Move::arc, is no straight line).
bool continues(const Move& a, const Move& b) {
  if (b.rapid || b.arc > 0 || b.tool != a.tool || b.from.tip.x != a.to.tip.x ||
      b.from.tip.y != a.to.tip.y)
    return false;
  const double ax = a.to.tip.x - a.from.tip.x, ay = a.to.tip.y - a.from.tip.y;
  const double bx = b.to.tip.x - b.from.tip.x, by = b.to.tip.y - b.from.tip.y;
  const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
  return lb > 0 && std::fabs(ax * by - ay * bx) <= 1e-9 * la * lb && ax * bx + ay * by > 0;
}

// Clips p + t d, t in [0, 1], to the box; false when nothing is left.
bool clipToBox(Xy& a, Xy& b, double x0, double y0, double x1, double y1) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t0 = 0, t1 = 1;
  auto edge = [&](double p, double q) {  // keeps p t <= q (Liang-Barsky)
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
    return true;
  };
  if (!edge(-dx, a.x - x0) || !edge(dx, x1 - a.x) || !edge(-dy, a.y - y0) || !edge(dy, y1 - a.y))
    return false;
  const Xy from = a;
  a = {from.x + t0 * dx, from.y + t0 * dy};
  b = {from.x + t1 * dx, from.y + t1 * dy};
  return t1 > t0;
}

double moveRadius(const Job& job, const Move& m) {
  return m.tool < job.path.cutters.size() ? job.path.cutters[m.tool].radius : job.cutter.radius;
}

// Whether a move cuts along a straight xy segment of some length.
bool straightCut(const Move& m) {
  const double dx = m.to.tip.x - m.from.tip.x, dy = m.to.tip.y - m.from.tip.y;
  return !m.rapid && m.arc <= 0 && dx * dx + dy * dy > 0;
}

// The line of the straight run of moves first..last (0-based), named by `what`, less
// one cutter radius at both ends, clipped to the cell centres; or the reason there is
// none.
json runLine(const Job& job, const GridSpec& g, size_t first, size_t last, size_t named,
             const std::string& what) {
  const std::vector<Move>& moves = job.path.moves;
  const double radius = moveRadius(job, moves[named]);
  Xy a{moves[first].from.tip.x, moves[first].from.tip.y};
  Xy b{moves[last].to.tip.x, moves[last].to.tip.y};
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  json line = {{"move", named + 1}};
  if (named < job.moveLines.size()) line["file_line"] = job.moveLines[named];
  const json passMoves = {first + 1, last + 1};
  if (!(length > 2 * radius))
    return {{"pass_moves", passMoves}, {"reason", what + " is not longer than two cutter radii"}};
  const Xy u{(b.x - a.x) / length, (b.y - a.y) / length};
  a = {a.x + radius * u.x, a.y + radius * u.y};
  b = {b.x - radius * u.x, b.y - radius * u.y};
  if (g.nx < 2 || g.ny < 2 ||
      !clipToBox(a, b, g.cellCentreX(0), g.cellCentreY(0), g.cellCentreX(g.nx - 1),
                 g.cellCentreY(g.ny - 1)))
    return {{"pass_moves", passMoves},
            {"reason", what + ", less a cutter radius at each end, does not cross the map"}};
  const int64_t samples =
      int64_t(std::floor(std::hypot(b.x - a.x, b.y - a.y) / g.spacing + 1e-9)) + 1;
  if (samples < 3)
    return {{"pass_moves", passMoves}, {"reason", what + " crosses fewer than 3 cells of the map"}};
  line["from"] = {a.x, a.y};
  line["to"] = {b.x, b.y};
  line["step_mm"] = g.spacing;
  line["samples"] = samples;
  line["pass_moves"] = passMoves;
  line["sampling"] = kSampling;
  return {{"line", line}};
}

// The first and last move of the straight run holding move k.
std::pair<size_t, size_t> runAround(const std::vector<Move>& moves, size_t k) {
  size_t first = k, last = k;
  while (first > 0 && continues(moves[first - 1], moves[first])) --first;
  while (last + 1 < moves.size() && continues(moves[last], moves[last + 1])) ++last;
  return {first, last};
}

// The centre line (feed_mark_report.h), or the reason there is none.
json centreLine(const Job& job, const GridSpec& g) {
  const std::vector<Move>& moves = job.path.moves;
  const double cx = g.originX + 0.5 * double(g.nx) * g.spacing;
  const double cy = g.originY + 0.5 * double(g.ny) * g.spacing;
  size_t best = moves.size();
  double bestDistance = HUGE_VAL;
  for (size_t k = 0; k < moves.size(); ++k) {
    const Move& m = moves[k];
    if (!straightCut(m)) continue;
    const double dx = m.to.tip.x - m.from.tip.x, dy = m.to.tip.y - m.from.tip.y;
    const double len2 = dx * dx + dy * dy;
    const double t =
        std::clamp(((cx - m.from.tip.x) * dx + (cy - m.from.tip.y) * dy) / len2, 0.0, 1.0);
    const double d = std::hypot(m.from.tip.x + t * dx - cx, m.from.tip.y + t * dy - cy);
    if (d < bestDistance) bestDistance = d, best = k;
  }
  if (best == moves.size()) return {{"reason", "no cutting move moves in x or y"}};
  const auto [first, last] = runAround(moves, best);
  json line = runLine(job, g, first, last, best,
                      "the pass nearest the map centre (move " + std::to_string(best + 1) + ")");
  return line;
}

// A prediction's entry in the plan: "predicted", or "predicted_reason" saying why not.
void addPrediction(const FeedMarkPrediction& p, json& plan) {
  if (!p.applicable) {
    plan["predicted_reason"] = p.reason;
    return;
  }
  std::vector<double> valleyDepthsUm;
  for (const double d : p.valleyDepthsMm) valleyDepthsUm.push_back(d * 1e3);
  json j = {{"formula",
             "the lower envelope of the teeth's arcs of radius rho_f; without tooth errors "
             "h = rho_f - sqrt(rho_f^2 - s^2 / 4) ~ s^2 / (8 rho_f), s the spacing"},
            {"profile_radius_mm", p.profileRadiusMm},
            {"spacing_mm", p.spacingMm},
            {"peak_to_valley_um", p.heightMm * 1e3},
            {"peak_to_valley_parabola_um", p.heightParabolaMm * 1e3},
            {"cutting_teeth", p.cuttingTeeth},
            {"valley_depths_um", valleyDepthsUm},
            {"regime", p.regime}};
  if (p.hasRunoutThreshold) j["runout_threshold_mm"] = p.runoutThresholdMm;
  plan["predicted"] = j;
}

// Whether the raster's neighbouring passes, a step-over w to each side, may cut into
// the centre line's marks: the closed form is one pass's, and a neighbour's envelope on
// this line is F(w) above the floor (analysis/pass_section.h). Where F(w) is at least the
// marks' height h (the pass section's reach at h is less than w on both sides, zigzag's
// mirrored passes included), no neighbour reaches the marks' peaks and the closed form
// holds (the closed form is for lead alone, so the line, under the tip, runs along the
// floor). Otherwise the neighbours cut the
// line with their own marks, whose spindle phase depends on the path before them (pass lengths,
// rapids): in phase with this pass's they leave its marks as predicted, out of phase they lower the
// peaks.
void addNeighbours(const Job& job, const FeedMarkPrediction& p, json& plan) {
  const PassSection section = PassSection::of(job.cutter, job.raster.leadDeg, job.raster.tiltDeg);
  const double w = job.raster.stepOver;
  bool reach = false;
  for (const int sign : {1, -1}) {
    const SectionSide side = section.side(p.heightMm, sign);
    reach = reach || !side.reachable || side.offset.high >= w;
  }
  plan["predicted"]["neighbouring_passes"] = {
      {"step_over_mm", w},
      {"may_cut_the_marks", reach},
      {"note", reach ? "the passes beside this one reach this line less than the marks' height "
                       "above its floor: where their marks are out of phase with this pass's "
                       "they lower its peaks, and the measured peak-to-valley is smaller than "
                       "the closed form's"
                     : "the passes beside this one stay above the marks' peaks on this line: "
                       "the closed form is the whole story"}};
}

// The closed form for a raster (analysis/feed_mark_formula.h).
void addRasterPrediction(const Job& job, json& plan) {
  if (!job.isRaster) {
    plan["predicted_reason"] =
        "the closed form of the centre line is recorded for raster jobs; see each pass's";
    return;
  }
  const FeedMarkPrediction p = predictFeedMarks(job.cutter, job.raster.leadDeg, job.raster.tiltDeg,
                                                job.cutting.feedPerTooth);
  addPrediction(p, plan);
  if (p.applicable && plan.value("pass_count", 0) > 1) addNeighbours(job, p, plan);
}

// The closed form for the pass of moves first..last: a level straight run with one
// axis, feed per tooth and cutter, its lead and tilt measured against its own feed
// direction; otherwise the reason.
FeedMarkPrediction passPrediction(const Job& job, size_t first, size_t last) {
  const std::vector<Move>& moves = job.path.moves;
  const Move& m0 = moves[first];
  const Vec3 axis = m0.from.axis;
  const double fz = m0.feedPerTooth > 0 ? m0.feedPerTooth : job.cutting.feedPerTooth;
  FeedMarkPrediction none;
  for (size_t k = first; k <= last; ++k) {
    const Move& m = moves[k];
    if (m.from.tip.z != m0.from.tip.z || m.to.tip.z != m0.from.tip.z) {
      none.reason =
          "the pass is not level (its tip's z changes): the closed form is for a "
          "level pass";
      return none;
    }
    if (!(m.from.axis == axis) || !(m.to.axis == axis) ||
        (m.rotary > 0 && !job.path.rotary[m.rotary - 1].tcp)) {
      none.reason = "the tool axis turns along the pass";
      return none;
    }
    if ((m.feedPerTooth > 0 ? m.feedPerTooth : job.cutting.feedPerTooth) != fz) {
      none.reason = "the feed per tooth changes along the pass";
      return none;
    }
  }
  const Cutter& cutter = m0.tool < job.path.cutters.size() ? job.path.cutters[m0.tool] : job.cutter;
  const double dx = moves[last].to.tip.x - m0.from.tip.x, dy = moves[last].to.tip.y - m0.from.tip.y;
  const double length = std::hypot(dx, dy);
  const double fx = dx / length, fy = dy / length;  // the feed; across it (-fy, fx)
  const double along = axis.x * fx + axis.y * fy, across = -axis.x * fy + axis.y * fx;
  constexpr double kDeg = kDegPerRad;
  const double tiltDeg = std::asin(std::clamp(across, -1.0, 1.0)) * kDeg;
  const double leadDeg = std::atan2(along, axis.z) * kDeg;
  return predictFeedMarks(cutter, leadDeg, std::fabs(across) <= 1e-12 ? 0.0 : tiltDeg, fz);
}
// Every straight cutting run of the path (feed_mark_report.h "passes"), the first
// kMaxPasses of them listed.
constexpr size_t kMaxPasses = 64;
void addPasses(const Job& job, const GridSpec& g, json& plan) {
  const std::vector<Move>& moves = job.path.moves;
  json passes = json::array();
  size_t runs = 0, crossing = 0;
  for (size_t k = 0; k < moves.size(); ++k) {
    if (!straightCut(moves[k])) continue;
    const auto [first, last] = runAround(moves, k);
    k = last;
    ++runs;
    json pass =
        runLine(job, g, first, last, first,
                "the pass of moves " + std::to_string(first + 1) + ".." + std::to_string(last + 1));
    const bool listed = passes.size() < kMaxPasses;
    if (pass.contains("line")) {
      ++crossing;
      if (listed) addPrediction(passPrediction(job, first, last), pass);
    }
    if (listed) passes.push_back(pass);
  }
  plan["passes"] = passes;
  plan["pass_count"] = runs;
  plan["passes_crossing_the_map"] = crossing;
}

}  // namespace

json feedMarkPlan(const Job& job, const GridSpec& grid) {
  if (!job.cutting.teeth()) return nullptr;
  json plan = centreLine(job, grid);
  addPasses(job, grid, plan);
  addRasterPrediction(job, plan);
  return plan;
}

// The samples of a plan's line: as extractProfile places a sample in the cell-centre
// lattice (clamped onto it: the line was clipped to the centres' span, up to rounding).
void FeedMarkSampler::addLine(const json& line) {
  Profile p;
  p.x0 = line["from"][0].get<double>(), p.y0 = line["from"][1].get<double>();
  p.x1 = line["to"][0].get<double>(), p.y1 = line["to"][1].get<double>();
  p.stepMm = line["step_mm"].get<double>();
  const int64_t n = line["samples"].get<int64_t>();
  const GridSpec& g = grid_;
  auto index = [](double v, double origin, double spacing, int64_t cells) {
    return std::clamp((v - origin) / spacing - 0.5, 0.0, double(cells - 1));
  };
  Line l;
  l.stepMm = p.stepMm;
  for (int64_t k = 0; k < n; ++k) {
    const double fi = index(p.xAt(k), g.originX, g.spacing, g.nx);
    const double fj = index(p.yAt(k), g.originY, g.spacing, g.ny);
    Sample s;
    s.i0 = std::min<int64_t>(int64_t(fi), std::max<int64_t>(0, g.nx - 2));
    s.j0 = std::min<int64_t>(int64_t(fj), std::max<int64_t>(0, g.ny - 2));
    s.i1 = std::min(s.i0 + 1, g.nx - 1), s.j1 = std::min(s.j0 + 1, g.ny - 1);
    s.u = fi - double(s.i0), s.v = fj - double(s.j0);
    l.samples.push_back(s);
  }
  l.cells.assign(4 * l.samples.size(), std::numeric_limits<double>::quiet_NaN());
  lines_.push_back(std::move(l));
}

FeedMarkSampler::FeedMarkSampler(const json& plan, const GridSpec& grid)
    : plan_(plan), grid_(grid) {
  if (plan_.contains("line")) addLine(plan_["line"]);
  if (plan_.contains("passes"))
    for (const json& pass : plan_["passes"])
      if (pass.contains("line")) addLine(pass["line"]);
}

void FeedMarkSampler::add(const ZMap& map) {
  const int64_t j0 = map.grid().offsetJ, j1 = j0 + map.ny();
  for (Line& l : lines_)
    for (size_t k = 0; k < l.samples.size(); ++k) {
      const Sample& s = l.samples[k];
      const int64_t is[4] = {s.i0, s.i1, s.i0, s.i1}, js[4] = {s.j0, s.j0, s.j1, s.j1};
      for (int c = 0; c < 4; ++c)
        if (js[c] >= j0 && js[c] < j1) l.cells[4 * k + size_t(c)] = map.at(is[c], js[c] - j0);
    }
}

// Adds the measurement of line l to `out`.
void FeedMarkSampler::measure(const Line& l, json& out) {
  Profile p;
  p.stepMm = l.stepMm;
  for (size_t k = 0; k < l.samples.size(); ++k) {
    const Sample& s = l.samples[k];
    const double* c = &l.cells[4 * k];
    p.height.push_back((1 - s.u) * (1 - s.v) * c[0] + s.u * (1 - s.v) * c[1] +
                       (1 - s.u) * s.v * c[2] + s.u * s.v * c[3]);
  }
  const FeedMarks m = measureFeedMarks(p);
  out["peak_to_valley_um"] = m.peakToValleyMm * 1e3;
  out["valleys"] = m.valleysMm.size();
  out["mean_spacing_mm"] = m.valleysMm.size() >= 2 ? json(m.meanSpacingMm) : json(nullptr);
}

json FeedMarkSampler::report() const {
  json r = plan_;
  size_t next = 0;
  if (r.contains("line")) measure(lines_[next++], r);
  if (r.contains("passes"))
    for (json& pass : r["passes"])
      if (pass.contains("line")) measure(lines_[next++], pass);
  if (next > 0) r["spacing_method"] = spacingMethod();
  return r;
}

json feedMarksReport(const Job& job, const ZMap& map) {
  const json plan = feedMarkPlan(job, map.grid());
  if (plan.is_null()) return plan;
  FeedMarkSampler sampler(plan, map.grid());
  sampler.add(map);
  return sampler.report();
}

}  // namespace scallop
