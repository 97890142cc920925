// Reading only the moves that can reach the grid (tools/io/move_window.h): a window
// keeps exactly the moves whose bound (the tips' box grown by the cutter's reach) meets
// its cell lines, counted against a brute force over the whole file; moves the sweep
// merges are kept or left out together; and the heights of a window equal the same cells
// of the whole job, bit for bit, with the envelope and with the teeth model (whose
// spindle phase must carry across the moves left out).
#include "tools/io/move_window.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "raycast/simulation.h"
#include "tests/support/cli_harness.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

class MoveWindow : public test::CliFixture {
 protected:
  Job load(const std::string& name, const std::string& text) {
    return loadJobFile(write(name, text).string());
  }
  ZMap heights(const Job& job) {
    RunSettings settings;
    settings.quiet = true;
    return computeSimulation(job, settings).map;
  }
};

// Passes along x at y = 0.25 k (k = 0..23), a point every 0.125 mm from x = -1 to 7,
// z = -0.2 + 0.05 sin(x) (no two moves in a row collinear), or flat (`flat`: each pass
// one run the sweep merges); rapids 1 mm up between passes.
std::string passes(bool flat) {
  std::ostringstream out;
  out.precision(17);
  for (int k = 0; k < 24; ++k) {
    const double y = 0.25 * k;
    out << "\n";
    for (int i = 0; i <= 64; ++i) {
      const double x = -1 + 0.125 * i;
      out << x << " " << y << " " << (flat ? -0.2 : -0.2 + 0.05 * std::sin(3 * x + k)) << "\n";
    }
  }
  return out.str();
}

std::string job(const std::string& stock, const std::string& extra = "") {
  return R"({"tool": {"type": "ball", "radius": 0.5, "flutes": 2}, "stock": )" + stock +
         R"(, "grid": {"spacing": 0.0625}, "path": {"file": "p.txt"})" + extra + "}";
}

// The whole job's grid holds every move's reach: it keeps them all.
constexpr const char* kWhole = R"({"min": [-2, -1, -1], "max": [8, 7, 0]})";
constexpr const char* kWindow = R"({"min": [2, 3, -1], "max": [3, 4, 0]})";

TEST_F(MoveWindow, KeepsExactlyTheMovesThatCanReachIt) {
  write("p.txt", passes(false));
  const Job window = load("w.json", job(kWindow));
  const ToolPathFile all = readToolPathFile(path("p.txt"));
  // Brute force: every move's bound against the window's cell lines (a rapid: or the
  // stock's box, which reaches half a cell further). The axis is vertical: the reach is the radius.
  const GridSpec g = window.grid();
  const double x0 = g.cellCentreX(0), x1 = g.cellCentreX(g.nx - 1);
  const double y0 = g.cellCentreY(0), y1 = g.cellCentreY(g.ny - 1);
  size_t reaching = 0;
  for (const Move& m : all.path.moves) {
    const double r = 0.5 + 1e-9 + 1e-12 * 7;
    const bool meets = std::fmax(m.from.tip.x, m.to.tip.x) + r >= x0 &&
                       std::fmin(m.from.tip.x, m.to.tip.x) - r <= x1 &&
                       std::fmax(m.from.tip.y, m.to.tip.y) + r >= y0 &&
                       std::fmin(m.from.tip.y, m.to.tip.y) - r <= y1;
    const bool stock = std::fmax(m.from.tip.x, m.to.tip.x) + r >= 2 &&
                       std::fmin(m.from.tip.x, m.to.tip.x) - r <= 3 &&
                       std::fmax(m.from.tip.y, m.to.tip.y) + r >= 3 &&
                       std::fmin(m.from.tip.y, m.to.tip.y) - r <= 4;
    reaching += meets || (m.rapid && stock);
  }
  EXPECT_EQ(window.movesRead, all.path.moves.size());
  EXPECT_EQ(window.path.moves.size(), reaching);
  EXPECT_LT(reaching, all.path.moves.size() / 10);  // a small window keeps few
  // report.json says both counts and the read's rate.
  const test::CliRun r = run("simulate " + path("w.json") + " -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json read =
      nlohmann::json::parse(test::slurp(dir_ / "out" / "report.json")).at("path_file");
  EXPECT_EQ(read.at("moves_read"), all.path.moves.size());
  EXPECT_EQ(read.at("moves_kept"), reaching);
  EXPECT_GT(read.at("read_moves_per_second").get<double>(), 0);
  EXPECT_GT(read.at("read_mb_per_second").get<double>(), 0);
  EXPECT_GT(reaching, 10u);
  // Each move kept is one of the file's, at its line.
  for (size_t k = 0; k < window.path.moves.size(); ++k) {
    const int64_t line = window.moveLines[k];
    size_t at = 0;
    while (at < all.moveLines.size() && all.moveLines[at] != line) ++at;
    ASSERT_LT(at, all.moveLines.size());
    EXPECT_EQ(window.path.moves[k].from.tip, all.path.moves[at].from.tip);
    EXPECT_EQ(window.path.moves[k].to.tip, all.path.moves[at].to.tip);
  }
}

TEST_F(MoveWindow, MovesTheSweepMergesAreKeptTogether) {
  write("p.txt", passes(true));
  const Job window = load("w.json", job(kWindow));
  const ToolPathFile all = readToolPathFile(path("p.txt"));
  // A flat pass is one merged segment: a pass whose reach meets the window's rows is
  // kept whole (its 64 cutting moves), the others are left out whole.
  const GridSpec g = window.grid();
  const double y0 = g.cellCentreY(0) - 0.5, y1 = g.cellCentreY(g.ny - 1) + 0.5;
  size_t passesKept = 0;
  for (int k = 0; k < 24; ++k) passesKept += 0.25 * k >= y0 && 0.25 * k <= y1;
  EXPECT_EQ(window.path.cuttingMoves(), passesKept * 64);
  EXPECT_LT(window.path.cuttingMoves(), all.path.cuttingMoves());
}

// The cells of `window` and the same cells (same centres) of `whole`, bit for bit.
void expectSameCells(const ZMap& window, const ZMap& whole) {
  const GridSpec &w = window.grid(), &a = whole.grid();
  const int64_t di = std::llround((w.originX - a.originX) / a.spacing);
  const int64_t dj = std::llround((w.originY - a.originY) / a.spacing);
  int64_t differ = 0;
  for (int64_t j = 0; j < w.ny; ++j)
    for (int64_t i = 0; i < w.nx; ++i) {
      ASSERT_EQ(w.cellCentreX(i), a.cellCentreX(i + di));
      ASSERT_EQ(w.cellCentreY(j), a.cellCentreY(j + dj));
      differ += window.at(i, j) != whole.at(i + di, j + dj);
    }
  EXPECT_EQ(differ, 0);
}

TEST_F(MoveWindow, AWindowHasTheWholeJobsHeightsEnvelopeAndTeeth) {
  write("p.txt", passes(false));
  for (const std::string& cutting :
       {std::string(), std::string(R"(, "cutting": {"model": "teeth", "feed_per_tooth": 0.3})")}) {
    SCOPED_TRACE(cutting.empty() ? "envelope" : "teeth");
    const Job whole = load("a.json", job(kWhole, cutting));
    const Job window = load("w.json", job(kWindow, cutting));
    ASSERT_EQ(whole.path.moves.size(), whole.movesRead);
    ASSERT_LT(window.path.moves.size(), whole.path.moves.size());
    if (!cutting.empty()) {
      EXPECT_FALSE(window.path.phaseMarks.empty());
    }
    const ZMap w = heights(window), a = heights(whole);
    EXPECT_LT(w.minHeight(), -0.1);  // cut
    expectSameCells(w, a);
    if (cutting.empty()) continue;
    // Without the carried phase the teeth marks move: the marks matter here.
    Job unmarked = window;
    unmarked.path.phaseMarks.clear();
    const ZMap u = heights(unmarked);
    int64_t differ = 0;
    for (size_t k = 0; k < u.heights().size(); ++k) differ += u.heights()[k] != w.heights()[k];
    EXPECT_GT(differ, 0);
  }
}

}  // namespace
}  // namespace scallop
