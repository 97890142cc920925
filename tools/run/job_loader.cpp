#include "tools/run/job_loader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "analysis/vertex_normals.h"
#include "base/input_error.h"
#include "raycast/simulation.h"
#include "sweep/tool_path_sweep.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/memory_limits.h"

namespace scallop {

namespace {

// The tool path of a job with "path": {"file": ...}, and the cutter from its CUTTER/
// when the job has no "tool".
// The grid a path file's reader keeps the moves of (tools/io/move_window.h): none when
// the reach of the cutters is not known before reading (the cutter comes from the file),
// in a frame, or with a design (its lines leave the grid's columns).
std::optional<ReadWindow> readWindow(const Job& job) {
  if ((!job.hasTool && job.tools.empty()) || job.frame || job.design || job.normalDeviation)
    return std::nullopt;
  ReadWindow w;
  const SweepWindow cells = cellWindow(job.grid());
  w.x0 = cells.x0, w.y0 = cells.y0, w.x1 = cells.x1, w.y1 = cells.y1;
  w.stock = job.stock;
  w.cutting = job.cutting;
  std::vector<Cutter> cutters;
  if (job.hasTool) cutters.push_back(job.cutter);
  for (const auto& [number, cutter] : job.tools) cutters.push_back(cutter);
  for (const Cutter& c : cutters) {
    const Cutter swept = job.cutting.teeth() ? c.spindleEnvelope() : c;
    w.radius = std::max(w.radius, swept.radius);
    w.fluteLength = std::max(w.fluteLength, swept.fluteLength + c.teeth.axialReach());
  }
  if (job.hasTool) w.oneToolFlutes = job.cutter.teeth.flutes;
  else if (job.tools.size() == 1) w.oneToolFlutes = job.tools.begin()->second.teeth.flutes;
  return w;
}

void readPathFile(Job& job) {
  job.pathReadOptions = job.pathOptions();
  PathFileOptions first = job.pathReadOptions;  // a re-read as a stream keeps every move
  first.window = readWindow(job);
  ToolPathFile read = readToolPathFile(job.pathFile, first);
  job.movesRead = read.movesRead;
  job.pathFileBytes = read.fileBytes;
  job.pathReadSeconds = read.readSeconds;
  job.toolMoves = read.toolMoves;
  const bool multiTool = !read.path.cutters.empty();
  if (!job.hasTool && job.tools.empty() && !read.cutter)
    throw InputError("tool",
                     "missing; expected an object, or \"tools\" (or a CUTTER/ "
                     "statement in " +
                         job.pathFile + ")");
  if (!job.hasTool && job.tools.empty()) job.cutter = *read.cutter;
  if (!job.hasTool && multiTool) {
    // Summaries and estimates take the largest of the cutters used (job.h).
    job.cutter = read.path.cutters.front();
    for (const Cutter& c : read.path.cutters)
      if (c.radius + c.fluteLength > job.cutter.radius + job.cutter.fluteLength) job.cutter = c;
  }
  if (!job.tools.empty() && !multiTool && read.path.cuttingMoves() > 0) {
    // A file without tool changes (CL text, or APT without LOADTL) names no tool.
    if (job.tools.size() != 1)
      throw InputError("tools", "the " + read.format + " file " + job.pathFile +
                                    " has no tool changes to pick one of " +
                                    std::to_string(job.tools.size()) +
                                    " tools; give one \"tool\" (or one entry in \"tools\")");
    job.cutter = job.tools.begin()->second;
  }
  if (job.hasTool && multiTool) {
    // The job's one "tool" cuts every move (the file's CUTTER/s are only checked below).
    read.path.cutters.clear();
    read.toolNumbers.clear();
    for (Move& m : read.path.moves) m.tool = 0;
  }
  if (job.hasTool && read.cutter &&
      (read.cutter->type != job.cutter.type || read.cutter->radius != job.cutter.radius ||
       read.cutter->cornerRadius != job.cutter.cornerRadius))
    read.warnings.add(job.pathFile,
                      "its CUTTER/ differs from the job's \"tool\"; the job's "
                      "tool is used");
  checkPathMagnitudes(read.path, read.moveLines, job.pathFile);
  const std::string stockName =
      job.stockSolid ? "the solid stock " + job.stockStlFile
      : job.stockMap ? "the bounding box of the stock map " + job.stockGsfFile
                     : "the stock box";
  warnRapidsIntoStock(read, job.cutter, job.stock, job.pathFile, job.stockSolid.get(), stockName);
  job.path = std::move(read.path);
  job.moveLines = std::move(read.moveLines);
  job.pathWarnings = std::move(read.warnings);
  job.ignoredWords = std::move(read.ignored);
  job.toolNumbers = std::move(read.toolNumbers);
  job.pathFormat = read.format;
}

// Where move k came from: "file:line", or "path move k" for a raster.
std::string moveLine(const Job& job, size_t k) {
  return k < job.moveLines.size() ? job.pathFile + ":" + std::to_string(job.moveLines[k])
                                  : "path move " + std::to_string(k + 1);
}

// The teeth model needs a feed per tooth for every cutting move (its own, from G-code F
// and S, or the job's) and a straight tip (not a TCP-off turning move): refused here,
// naming the job's field or the file's line, before anything is swept.
void checkTeethInputs(const Job& job) {
  if (!job.cutting.teeth()) return;
  const ToolPath& path = job.path;
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& m = path.moves[k];
    if (m.rapid) continue;
    if (m.feedPerTooth <= 0 && job.cutting.feedPerTooth <= 0)
      throw InputError(
          "cutting.feed_per_tooth",
          job.isRaster
              ? "missing; the teeth model needs a feed per tooth (mm, > 0) for the raster"
              : "missing; the teeth model needs a feed per tooth (mm, > 0): the move of " +
                    moveLine(job, k) +
                    " carries none (G-code gives F / (S flutes) in G94 with S, F / flutes in "
                    "G95; G93 and other formats give none)");
    if (m.rotary > 0 && m.rotary <= path.rotary.size() && !path.rotary[m.rotary - 1].tcp)
      throw InputError(moveLine(job, k),
                       "the teeth cutting model needs a straight tip motion; a move that turns "
                       "the rotary axes with TCP off (its tip follows a curve) is not supported "
                       "with teeth");
  }
}

// A mesh of the part in frame coordinates (a rigid motion: the facets keep their
// winding and outside).
TriangleMesh meshInFrame(const TriangleMesh& mesh, const GridFrame& frame) {
  TriangleMesh out = mesh;
  for (Vec3& p : out.vertices) p = frame.pointToFrame(p);
  for (Vec3& n : out.normals) n = frame.directionToFrame(n);
  return out;
}

// With a frame: what a frame cannot hold refused, and the path moved into the frame's
// coordinates (raycast/grid_frame.h). Moves that stay below -depth cannot reach the map
// and become rapids (not swept); every other cutting move must point its axis to the
// normal side (k >= 0 in the frame), as k >= 0 is required without a frame.
void placePathInFrame(Job& job) {
  const GridFrame& frame = *job.frame;
  if (job.shapedStock())
    throw InputError("grid.frame",
                     "a stock of any shape (stock.stl, stock.gsf) is not supported in a frame; "
                     "give the stock as a box or leave out grid.frame");
  if (!job.path.rotary.empty())
    throw InputError("grid.frame",
                     "a 5-axis machine's rotary moves (\"machine\") are not supported in a frame; "
                     "write the path as CL data (tip and axis) or leave out grid.frame");
  if (job.cutting.teeth())
    throw InputError("grid.frame",
                     "the teeth cutting model is not supported in a frame; use cutting.model "
                     "\"envelope\" or leave out grid.frame");
  if (job.normalDeviation)
    throw InputError("grid.frame",
                     "the design's normal deviation does not depend on the map's frame (it "
                     "measures along the design's own normals): run it in a job without "
                     "grid.frame");
  // The design seen in the frame: its height along the normal on each cell's line is
  // then the vertical comparison's design height (analysis/design_deviation.h).
  if (job.design)
    job.design = std::make_shared<const TriangleMesh>(meshInFrame(*job.design, frame));
  job.path = pathInFrame(job.path, frame);
  for (size_t k = 0; k < job.path.moves.size(); ++k) {
    Move& m = job.path.moves[k];
    if (m.rapid) continue;
    const Cutter& c = job.path.cutters.empty() ? job.cutter : job.path.cutters[m.tool];
    // No point of the cutter is further than R + flute length from its tip.
    if (std::fmax(m.from.tip.z, m.to.tip.z) + c.radius + c.fluteLength < -frame.depth) {
      m.rapid = true;
      continue;
    }
    const double k0 = std::fmin(m.from.axis.z, m.to.axis.z);
    if (k0 < 0)
      throw InputError(
          moveLine(job, k),
          "the tool axis points away from grid.frame.normal (k = " + std::to_string(k0) +
              " in the frame): a height map along the normal cannot show "
              "what it cuts; scallop needs k >= 0 in the frame, or a "
              "grid.frame.depth that leaves the move below the map");
  }
}

// The normal deviation moves each move into the frame of each vertex line: the part
// frame's CL data only (rotary moves are machine angles of the part frame), with the
// envelope, and a design whose facets agree on their outside.
void checkNormalDeviationInputs(const Job& job) {
  if (!job.path.rotary.empty())
    throw InputError("design.normal_deviation",
                     "a 5-axis machine's rotary moves (\"machine\") are not supported; write "
                     "the path as CL data (tip and axis) or leave out normal_deviation");
  if (job.cutting.teeth())
    throw InputError("design.normal_deviation",
                     "the teeth cutting model is not supported; use cutting.model \"envelope\" "
                     "or leave out normal_deviation");
  requireConsistentOrientation(*job.design, job.designFile);
}

}  // namespace

void loadJobInputs(Job& job, bool checkMemory) {
  try {
    if (checkMemory) checkGridFitsMemory(job.grid(), "grid.spacing");
    if (!job.designFile.empty())
      job.design = std::make_shared<const TriangleMesh>(readStl(job.designFile));
    if (job.isRaster) {
      checkRasterFitsMemory(job);
      job.path = makeRaster(job.cutter, job.stock, job.raster);
    } else {
      readPathFile(job);
    }
    checkTeethInputs(job);
    if (job.frame) placePathInFrame(job);
    if (job.normalDeviation) checkNormalDeviationInputs(job);
  } catch (const InputError& e) {
    throwFromJob(e, job.source);
  }
}

bool pathStreams(const Job& job) {
  return !job.isRaster && !job.pathFile.empty() && !job.frame;
}

size_t streamJobPath(const Job& job, size_t partMoves,
                     const std::function<void(ToolPath&)>& takePart) {
  // readPathFile: without cutters of the file's own, every move cuts with the job's tool.
  const bool oneTool = job.path.cutters.empty();
  const ToolPathFile read =
      streamToolPathFile(job.pathFile, job.pathReadOptions, partMoves, [&](ToolPath& part) {
        if (oneTool)
          for (Move& m : part.moves) m.tool = 0;
        takePart(part);
      });
  return read.movesHandedOver;
}

void releasePathMoves(Job& job) {
  std::vector<Move>().swap(job.path.moves);
  std::vector<int64_t>().swap(job.moveLines);
}

Job loadJob(const std::string& text, const std::string& source, bool checkMemory,
            const std::string& pathOverride, bool arcChords) {
  Job job = parseJob(text, source, pathOverride);
  if (arcChords) job.arcChords = true;
  loadJobInputs(job, checkMemory);
  return job;
}

Job loadJobFile(const std::string& path, bool checkMemory, const std::string& pathOverride,
                bool arcChords) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "is a folder, expected a job file (JSON)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the job file");
  std::ostringstream text;
  text << in.rdbuf();
  return loadJob(text.str(), path, checkMemory, pathOverride, arcChords);
}

}  // namespace scallop
