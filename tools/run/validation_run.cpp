#include "tools/run/validation_run.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <utility>

#include "analysis/path_interval.h"
#include "analysis/seed_tables.h"
#include "analysis/simulated_interval.h"
#include "analysis/tool_conditions.h"
#include "tools/io/atomic_file.h"
#include "tools/render/svg_plot.h"
#include "tools/run/interval_comparison.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The printed tables themselves are in analysis/seed_tables.h.

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"};

// ---- Pictures -----------------------------------------------------------------------------

struct Marker {
  std::string name;
  double halfIntervalMm;
  std::string colour;
};

// The simulated cross-feed profile of one pass (height above the floor, um, against the
// distance from the pass's centre line, mm) with the target h, the simulated exact L/2
// and each procedure's L/2; the legend gives the scallop each L/2 really leaves.
std::string profilePicture(const SimulatedPass& pass, const std::string& title, double h,
                           double exactL2, const std::vector<Marker>& markers) {
  double xMax = exactL2;
  for (const Marker& m : markers) xMax = std::max(xMax, m.halfIntervalMm);
  xMax = std::min(1.15 * xMax, pass.reachPlusMm());
  const ScallopProfile p = pass.profile(0, xMax, xMax / 600);
  std::vector<double> x, y;
  double top = 1.5 * h;
  for (size_t k = 0; k < p.position.size(); ++k) {
    if (p.height[k] >= pass.ceilingMm()) break;
    x.push_back(p.position[k]);
    y.push_back(1000 * p.height[k]);
    top = std::max(top, p.height[k]);
  }
  SvgPlot plot;
  plot.setTitle(title);
  plot.setLabels("cross-feed distance from the pass's centre line [mm]",
                 "height above the floor [\xC2\xB5m]");
  plot.setRange(0, xMax, 0, 1000 * top * 1.04);
  plot.addLine(x, y, "#222", "simulated profile of one pass", 2.2);
  plot.addHorizontalLine(1000 * h, "#888", fmt::format("target h = {:g} \xC2\xB5m", 1000 * h), 1.5,
                         "6 4");
  plot.addVerticalLine(exactL2, "#222", fmt::format("simulated exact L/2 = {:.4f} mm", exactL2),
                       1.5, "6 4");
  for (const Marker& m : markers) {
    const SimulatedCusp cusp = pass.cusp(2 * m.halfIntervalMm);
    const std::string left = cusp.covered
                                 ? fmt::format("scallop {:.1f} \xC2\xB5m ({:+.1f} \xC2\xB5m)",
                                               1000 * cusp.heightMm, 1000 * (cusp.heightMm - h))
                                 : std::string("uncut strip");
    plot.addVerticalLine(m.halfIntervalMm, m.colour,
                         fmt::format("{} L/2 = {:.3f} mm: {}", m.name, m.halfIntervalMm, left),
                         1.8);
    plot.addPoint(m.halfIntervalMm, 1000 * pass.heightAboveFloor(m.halfIntervalMm), m.colour);
  }
  return plot.render();
}

// ---- The tables ---------------------------------------------------------------------------

struct Run {
  std::string outDir;
  std::vector<ValidationTable> tables;
  std::vector<std::string> pictures;  // relative to outDir

  void picture(const std::string& name, const std::string& svg) {
    const std::string rel = "profiles/" + name + ".svg";
    writeSvgFile((fs::path(outDir) / rel).string(), svg);
    pictures.push_back(rel);
  }
};

json valueOrNull(const ProcedureResult& r) {
  return r.applicable ? json(r.value) : json(nullptr);
}

void seed000(Run& run) {
  for (int which = 0; which < 2; ++which) {
    const int lTable = 2 + which;
    ValidationTable lt{
        fmt::format("seed000_table{}", lTable),
        fmt::format("Seed 000 Table {}: L/2 by each procedure, R = {} mm, Rcr = {} mm; "
                    "simulated truth beside the printed values",
                    lTable, 3 * (which + 1), which + 1),
        {"condition", "rho_deg", "h_mm", "procedure", "printed_half_interval_mm",
         "computed_half_interval_mm", "simulated_scallop_at_printed_mm", "scallop_error_um",
         "simulated_scallop_at_computed_mm", "simulated_exact_half_interval_mm",
         "printed_minus_exact_um"},
        {}};
    ValidationTable ht{
        fmt::format("seed000_table{}", lTable + 2),
        fmt::format("Seed 000 Table {}: h from the printed computational L/2, R = {} mm, "
                    "Rcr = {} mm; the simulated (true) scallop of that L/2 beside",
                    lTable + 2, 3 * (which + 1), which + 1),
        {"condition", "rho_deg", "printed_half_interval_mm", "procedure", "printed_h_mm",
         "computed_h_mm", "simulated_h_mm", "printed_minus_simulated_um",
         "computed_minus_simulated_um"},
        {}};
    for (const Seed000Condition& c : kSeed000) {
      if (c.lengthTable != lTable) continue;
      const SimulatedPass pass(Cutter::make(CutterType::Bull, c.radius, c.cornerRadius), c.leadDeg,
                               0);
      const SideIntervals exact = pass.halfIntervals(c.h);
      const double trueH = pass.cusp(2 * c.halfInterval[0]).heightMm;
      std::vector<Marker> markers;
      for (int p = 0; p < kSeed000Procedures; ++p) {
        const ProcedureInfo& procedure = kProcedures[p];
        const ProcedureResult l2 = procedure.halfInterval(c.radius, c.cornerRadius, c.leadDeg, c.h,
                                                          kComputationalEpsilonMm);
        const double atPrinted = pass.cusp(2 * c.halfInterval[p]).heightMm;
        lt.rows.push_back({c.condition, c.leadDeg, c.h, procedure.name, c.halfInterval[p],
                           valueOrNull(l2), atPrinted, 1000 * (atPrinted - c.h),
                           l2.applicable ? json(pass.cusp(2 * l2.value).heightMm) : json(nullptr),
                           exact.halfIntervalMm(),
                           1000 * (c.halfInterval[p] - exact.halfIntervalMm())});
        const ProcedureResult h = procedure.scallopHeight(
            c.radius, c.cornerRadius, c.leadDeg, c.halfInterval[0], kComputationalEpsilonMm);
        ht.rows.push_back({c.condition, c.leadDeg, c.halfInterval[0], procedure.name, c.scallop[p],
                           valueOrNull(h), trueH, 1000 * (c.scallop[p] - trueH),
                           h.applicable ? json(1000 * (h.value - trueH)) : json(nullptr)});
        markers.push_back({procedure.name, c.halfInterval[p], kColours[p]});
      }
      run.picture(fmt::format("seed000_table{}_condition{}", lTable, c.condition),
                  profilePicture(
                      pass,
                      fmt::format("Seed 000 Table {} condition {}: bull R = {:g}, Rcr = {:g} mm, "
                                  "\xCF\x81 = {:g}\xC2\xB0, h = {:g} mm (printed L/2)",
                                  lTable, c.condition, c.radius, c.cornerRadius, c.leadDeg, c.h),
                      c.h, exact.halfIntervalMm(), markers));
    }
    run.tables.push_back(lt);
    run.tables.push_back(ht);
  }
  std::swap(run.tables[1], run.tables[2]);  // Tables 2, 3, 4, 5 in order
}

void seed001(Run& run) {
  const std::vector<std::string> cols = {"condition",
                                         "radius_mm",
                                         "corner_radius_mm",
                                         "lead_deg",
                                         "h_mm",
                                         "printed_half_interval_mm",
                                         "computed_half_interval_mm",
                                         "simulated_scallop_at_printed_mm",
                                         "scallop_error_um",
                                         "simulated_exact_half_interval_mm",
                                         "printed_minus_exact_um"};
  ValidationTable t1{
      "seed001_table1", "Seed 001 Table 1: ball end mill L/2 (Eq. 1), no inclination", cols, {}};
  ValidationTable t2{"seed001_table2",
                     "Seed 001 Table 2: filleted end mill L/2 (computational), theta = 5 deg",
                     cols,
                     {}};
  const std::vector<std::string> tcCols = {
      "condition", "radius_mm", "corner_radius_mm",       "h_mm",     "parameter", "unit",
      "printed",   "computed",  "computed_minus_printed", "simulated"};
  const char* const notSimulated = "n/a";  // a tool condition parameter, not a surface height
  ValidationTable t3{"seed001_table3",
                     "Seed 001 Table 3: ball end mill sl_fd and v_cs (ap = 0.5 mm); tool condition "
                     "parameters, not surface heights: nothing to simulate",
                     tcCols,
                     {}};
  ValidationTable t4{
      "seed001_table4",
      "Seed 001 Table 4: filleted end mill sl_fd and v_cs (ap = 0.5 mm, theta = 5 deg); "
      "tool condition parameters, not surface heights: nothing to simulate",
      tcCols,
      {}};
  auto conditions = [&](ValidationTable& t, const char* name, double R, double r, double h,
                        const ToolConditions& a, const ToolConditions& b, const double printed[4]) {
    const char* params[] = {"sl_fd(1)", "sl_fd(2)", "v_cs(1)", "v_cs(2)"};
    const char* units[] = {"mm", "mm", "m/min", "m/min"};
    const double computed[] = {a.frictionalDistanceMm, b.frictionalDistanceMm,
                               a.cuttingSpeedMPerMin, b.cuttingSpeedMPerMin};
    for (int k = 0; k < 4; ++k)
      t.rows.push_back({name, R, r, h, params[k], units[k], printed[k], computed[k],
                        computed[k] - printed[k], notSimulated});
  };
  for (int i = 0; i < kSeed001Columns; ++i) {
    for (const Seed001Column* c : {&kSeed001Ball[i], &kSeed001Filleted[i]}) {
      const bool filleted = c->cornerRadius > 0;
      const Cutter cutter = filleted ? Cutter::make(CutterType::Bull, c->radius, c->cornerRadius)
                                     : Cutter::make(CutterType::Ball, c->radius);
      const double lead = filleted ? kSeed001InclinationDeg : 0;
      const double printed = c->halfInterval;
      const SimulatedPass pass(cutter, lead, 0);
      const SideIntervals exact = pass.halfIntervals(c->h);
      const ProcedureResult l2 =
          filleted ? halfIntervalComputational(c->radius, c->cornerRadius, lead, c->h)
                   : halfIntervalBall(c->radius, c->h);
      const double atPrinted = pass.cusp(2 * printed).heightMm;
      (filleted ? t2 : t1)
          .rows.push_back({c->name, c->radius, filleted ? json(c->cornerRadius) : json(nullptr),
                           lead, c->h, printed, valueOrNull(l2), atPrinted,
                           1000 * (atPrinted - c->h), exact.halfIntervalMm(),
                           1000 * (printed - exact.halfIntervalMm())});
      const std::string procedure = filleted ? "computational" : "ball";
      const std::string tool =
          filleted ? fmt::format("bull R = {:g}, Rcr = {:g} mm, \xCE\xB8 = 5\xC2\xB0", c->radius,
                                 c->cornerRadius)
                   : fmt::format("ball R = {:g} mm", c->radius);
      run.picture(fmt::format("seed001_table{}_{}", filleted ? 2 : 1, c->name),
                  profilePicture(pass,
                                 fmt::format("Seed 001 Table {} {}: {}, h = {:g} mm (printed L/2)",
                                             filleted ? 2 : 1, c->name, tool, c->h),
                                 c->h, exact.halfIntervalMm(),
                                 {{procedure, printed, kColours[filleted ? 0 : 4]}}));
    }
    const Seed001Column& b = kSeed001Ball[i];
    const double ballPrinted[] = {b.sl1, b.sl2, b.v1, b.v2};
    conditions(t3, b.name, b.radius, 0, b.h,
               ballFirstPass(b.radius, kSeed001DepthOfCutMm, b.spindle),
               ballLaterPass(b.radius, b.h, b.spindle), ballPrinted);
    const Seed001Column& f = kSeed001Filleted[i];
    const double filPrinted[] = {f.sl1, f.sl2, f.v1, f.v2};
    conditions(t4, f.name, f.radius, f.cornerRadius, f.h,
               filletedFirstPass(f.radius, f.cornerRadius, kSeed001InclinationDeg,
                                 kSeed001DepthOfCutMm, f.spindle),
               filletedLaterPass(f.radius, f.cornerRadius, kSeed001InclinationDeg, f.h, f.spindle),
               filPrinted);
  }
  for (ValidationTable* t : {&t1, &t2, &t3, &t4}) run.tables.push_back(*t);
}

// Beyond the seeds: the procedures that take any cutter, lead and tilt, each
// L/2 beside the simulated exact one and the scallop two simulated passes 2 L/2 apart
// leave. The conditions cover what seed 000's procedures cannot: tilts and a flat end
// mill.
void anyCutter(Run& run) {
  struct Condition {
    const char* name;
    CutterType type;
    double radius, cornerRadius, leadDeg, tiltDeg, h;
  };
  const Condition conditions[] = {{"ball_tilted", CutterType::Ball, 3, 0, 10, -5, 0.05},
                                  {"bull_lead", CutterType::Bull, 6, 2, 10, 0, 0.1},
                                  {"bull_lead5_tilt7", CutterType::Bull, 3, 1, 5, 7, 0.05},
                                  {"bull_lead10_tilt20", CutterType::Bull, 3, 1, 10, 20, 0.05},
                                  {"flat_lead", CutterType::Flat, 3, 0, 10, 0, 0.05}};
  ValidationTable t{"any_cutter",
                    "The exact procedure and the effective radius at the contact (any cutter, "
                    "lead and tilt) against the simulated truth",
                    {"condition", "tool", "radius_mm", "corner_radius_mm", "lead_deg", "tilt_deg",
                     "h_mm", "procedure", "half_interval_mm", "simulated_exact_half_interval_mm",
                     "minus_exact_um", "simulated_scallop_mm", "scallop_error_um"},
                    {}};
  for (const Condition& c : conditions) {
    const SimulatedPass pass(Cutter::make(c.type, c.radius, c.cornerRadius), c.leadDeg, c.tiltDeg);
    const IntervalComparison cmp = compareIntervals(pass, c.h);
    for (const ProcedureComparison& p : cmp.procedures) {
      if (p.name != "exact" && p.name != "effective_radius") continue;
      const bool simulated = p.applicable && p.cusp.covered;
      const double exact = cmp.exact.halfIntervalMm();
      t.rows.push_back({c.name, toString(c.type), c.radius,
                        c.type == CutterType::Bull ? json(c.cornerRadius) : json(nullptr),
                        c.leadDeg, c.tiltDeg, c.h, p.name,
                        p.applicable ? json(p.halfIntervalMm) : json(nullptr), exact,
                        p.applicable ? json(1000 * (p.halfIntervalMm - exact)) : json(nullptr),
                        simulated ? json(p.cusp.heightMm) : json(nullptr),
                        simulated ? json(1000 * (p.cusp.heightMm - c.h)) : json(nullptr)});
    }
  }
  run.tables.push_back(t);
}

}  // namespace

ValidationResult runValidation(const ValidationSettings& args) {
  ensureWritableDirectory(args.outDir);
  ensureWritableDirectory((fs::path(args.outDir) / "profiles").string());
  Run run;
  run.outDir = args.outDir;
  seed000(run);
  seed001(run);
  anyCutter(run);

  json doc;
  doc["output_dir"] = args.outDir;
  doc["tables"] = json::object();
  for (const ValidationTable& t : run.tables) {
    const std::string file = t.name + ".csv";
    writeTextAtomically((fs::path(args.outDir) / file).string(), tableCsv(t), "the file");
    json rows = json::array();
    for (const auto& row : t.rows) {
      json r;
      for (size_t c = 0; c < row.size(); ++c) r[t.columns[c]] = row[c];
      rows.push_back(r);
    }
    doc["tables"][t.name] = {{"title", t.title}, {"file", file}, {"rows", rows}};
  }
  doc["pictures"] = run.pictures;
  doc["units"] = {{"length", "mm"}, {"error", "um"}, {"angle", "deg"}};
  return {std::move(run.tables), std::move(run.pictures), std::move(doc)};
}

}  // namespace scallop
