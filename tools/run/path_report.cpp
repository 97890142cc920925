#include "tools/run/path_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "analysis/design_deviation.h"
#include "tools/io/job.h"
#include "tools/io/job_cutters.h"
#include "tools/render/deviation_png.h"

namespace scallop {

using nlohmann::json;

json pathFileReport(const Job& job, bool quiet) {
  const PathWarnings& w = job.pathWarnings;
  if (!quiet) {
    for (size_t k = 0; k < std::min<size_t>(w.kept.size(), 20); ++k)
      std::fprintf(stderr, "scallop: warning: %s\n", w.kept[k].c_str());
    if (w.total > 20) std::fprintf(stderr, "scallop: %zu warnings in all\n", w.total);
  }
  json ignored = json::array();
  for (const IgnoredWords::Entry& e : job.ignoredWords.entries)
    ignored.push_back(
        {{"word", e.word}, {"meaning", e.meaning}, {"count", e.count}, {"lines", e.lines}});
  // The read: every move of the file, those kept (that can reach the grid), the rate.
  const double seconds = job.pathReadSeconds;
  json r = {{"format", job.pathFormat},
            {"moves_read", job.movesRead},
            {"moves_kept", job.path.moves.size()},
            {"read_seconds", seconds},
            {"read_mb_per_second", seconds > 0 ? job.pathFileBytes / 1e6 / seconds : 0.0},
            {"read_moves_per_second", seconds > 0 ? double(job.movesRead) / seconds : 0.0},
            {"warnings", w.kept},
            {"warnings_total", w.total},
            {"ignored_words", ignored}};
  const std::vector<Cutter>& cutters = job.path.cutters;
  if (!cutters.empty()) {
    // The tools of a multi-tool program, each with the cutting moves it makes.
    std::vector<int64_t> moves(cutters.size(), 0), first(cutters.size(), 0),
        last(cutters.size(), 0);
    // Of every move read when the reader left some out (tools/io/move_window.h).
    if (!job.toolMoves.empty()) {
      for (size_t t = 0; t < cutters.size() && t < job.toolMoves.size(); ++t)
        moves[t] = job.toolMoves[t].count, first[t] = job.toolMoves[t].firstLine,
        last[t] = job.toolMoves[t].lastLine;
    } else {
      for (size_t k = 0; k < job.path.moves.size(); ++k) {
        const Move& m = job.path.moves[k];
        if (m.rapid || m.tool >= cutters.size()) continue;
        const int64_t line = k < job.moveLines.size() ? job.moveLines[k] : 0;
        if (moves[m.tool]++ == 0) first[m.tool] = line;
        last[m.tool] = line;
      }
    }
    json tools = json::array();
    for (size_t t = 0; t < cutters.size(); ++t) {
      const Cutter& c = cutters[t];
      tools.push_back({{"number", t < job.toolNumbers.size() ? job.toolNumbers[t] : int64_t(t + 1)},
                       {"tool", cutterToJson(c)},
                       {"cutting_moves", moves[t]},
                       {"first_line", first[t]},
                       {"last_line", last[t]}});
    }
    r["tools"] = tools;
    if (!quiet)
      for (size_t t = 0; t < cutters.size(); ++t)
        std::fprintf(stderr, "tool T%lld: %s R = %g mm, %lld cutting moves\n",
                     (long long)(t < job.toolNumbers.size() ? job.toolNumbers[t] : int64_t(t + 1)),
                     toString(cutters[t].type), cutters[t].radius, (long long)moves[t]);
  }
  return r;
}

json designReport(const Job& job, const ZMap& map, const std::string& outDir, bool quiet) {
  const MeshIndex index(*job.design);
  DesignComparison c = compareWithDesign(map, index, job.gougeTolerance);
  // MoveFinder traces a height to the moves whose swept solid of revolution reaches it;
  // the teeth leave heights above that envelope, so with teeth the gouges are reported
  // without their moves (docs/teeth.md).
  const bool traced = !job.cutting.teeth();
  if (traced)
    attributeGouges(c, map, job.cutter, job.path);
  else if (!quiet && !c.gouges.empty())
    std::fprintf(stderr,
                 "scallop: warning: design: with the teeth cutting model the gouges are not "
                 "traced to their moves (the move finder sweeps the envelope)\n");
  double limit = 0;
  if (!outDir.empty()) {
    const std::string png = (std::filesystem::path(outDir) / "deviation.png").string();
    limit = writeDeviationPng(
        c, png, "machined - design: " + std::filesystem::path(job.designFile).filename().string());
  }

  const DeviationSummary& s = c.summary;
  json gouges = json::array();
  for (size_t n = 0; n < std::min<size_t>(c.gouges.size(), 100); ++n) {
    const Gouge& g = c.gouges[n];
    json moves = json::array();
    for (size_t k = 0; k < std::min<size_t>(g.moves.size(), 20); ++k) {
      json m = {{"move", g.moves[k] + 1}};
      if (g.moves[k] < job.moveLines.size()) m["line"] = job.moveLines[g.moves[k]];
      moves.push_back(m);
    }
    gouges.push_back({{"x", g.x},
                      {"y", g.y},
                      {"depth_mm", g.depth},
                      {"design_z", g.designZ},
                      {"machined_z", g.machinedZ},
                      {"cells", g.cells},
                      {"area_mm2", g.areaMm2},
                      {"moves", moves}});
  }
  const double maxDepth = c.gouges.empty() ? 0.0 : c.gouges.front().depth;
  json r = {{"stl", job.designFile},
            {"gouge_tolerance_mm", job.gougeTolerance},
            {"cells_compared", s.cells},
            {"deviation_mm", {{"min", s.min}, {"max", s.max}, {"mean", s.mean}, {"rms", s.rms}}},
            {"overcut",
             {{"cells", s.overcutCells},
              {"area_mm2", s.overcutAreaMm2},
              {"max_depth_mm", std::max(0.0, -s.min)}}},
            {"undercut",
             {{"cells", s.undercutCells},
              {"area_mm2", s.undercutAreaMm2},
              {"max_mm", std::max(0.0, s.max)}}},
            {"gouges",
             {{"count", c.gouges.size()},
              {"max_depth_mm", maxDepth},
              {"moves_traced", traced},
              {"deepest", gouges}}}};
  if (!outDir.empty()) {
    r["image"] = "deviation.png";
    r["image_colour_range_mm"] = limit;
  }
  if (!quiet) {
    std::fprintf(stderr,
                 "design: %lld cells compared, machined - design in [%.6f, %.6f] mm, rms %.6f "
                 "mm; %zu gouges deeper than %g mm",
                 (long long)s.cells, s.min, s.max, s.rms, c.gouges.size(), job.gougeTolerance);
    if (!c.gouges.empty()) {
      const Gouge& g = c.gouges.front();
      std::fprintf(stderr, ", deepest %.6f mm at (%.3f, %.3f)", g.depth, g.x, g.y);
      if (!g.moves.empty() && g.moves.front() < job.moveLines.size())
        std::fprintf(stderr, " by %s:%lld", job.pathFile.c_str(),
                     (long long)job.moveLines[g.moves.front()]);
    }
    std::fprintf(stderr, "\n");
  }
  return r;
}

}  // namespace scallop
