// Tool-path files: the cutter locations a CAM system writes, read by format.
//
// The format comes from the file name's extension:
//   .cl .apt .cls        APT / CL data (tools/io/apt_reader.h); a .cl file whose first
//                        statement starts with a number is plain CL text instead
//   .nc .ngc .gcode .tap G-code, 3-axis subset (tools/io/gcode_reader.h)
//   .txt                 plain CL text, below
//
// Plain CL text, one cutter location per line:
//   # comment lines start with '#'
//   x y z            tip position, axis +Z (3-axis), mm
//   x y z i j k      tip position and tool axis (normalised on reading)
//   (blank line)     ends a pass: the move to the next location is a rapid
// Consecutive locations are joined by linear cutting moves. This is the format of
// OpenCAMLib-style drop-cutter output (e.g. shared/data/mount_rush/*.cl.txt).
//
// Files are read line by line: only the moves themselves are held, never the text.
// Every reader throws InputError naming "file:line" and what was expected.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/stock_solid.h"
#include "base/vec3.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "tools/io/move_window.h"

namespace scallop {

// Warnings of one path file: the first kMaxKept are kept ("file:line: what"), all
// are counted, so a file with a million unknown statements stays readable.
struct PathWarnings {
  static constexpr size_t kMaxKept = 100;
  std::vector<std::string> kept;
  size_t total = 0;
  void add(const std::string& where, const std::string& what);
};

// Words a file holds that change nothing scallop simulates (feeds, spindle, coolant,
// tool length compensation...): each distinct word once, with what it means, how often
// it appears and its first lines, for report.json.
struct IgnoredWords {
  static constexpr size_t kMaxLines = 20;
  struct Entry {
    std::string word, meaning;
    size_t count = 0;
    std::vector<int64_t> lines;  // the first kMaxLines
  };
  std::vector<Entry> entries;  // in the order first met
  void add(const std::string& word, const std::string& meaning, int64_t line);
};

// A 5-axis machine for G-code rotary words (CONVENTIONS.md "Machines"): its
// kinematics and geometry, and the codes that switch TCP on and off (canonical text,
// gcodeWordText: "G43.4", "M128").
struct MachineSpec {
  TableMachine geometry;
  std::vector<std::string> tcpOn{"G43.4"}, tcpOff{"G49"};
};

struct PathFileOptions {
  // Arcs (G2/G3) are single moves whose tip follows the arc exactly; with arcChords
  // (the --arc-chords baseline) they become chords whose distance from the true arc is
  // at most arcTolerance, mm.
  bool arcChords = false;
  double arcTolerance = 1e-4;
  // G-code block delete: lines starting with '/' are skipped (on) or read (off).
  bool blockDelete = false;
  // G-code work offsets G54..G59: the job-frame position of each one's zero, mm.
  std::array<Vec3, 6> workOffsets{};
  // The job's "tools": T number -> cutter. Empty: the job has one tool.
  std::map<int64_t, Cutter> tools;
  // The job's "machine": G-code rotary words A/B/C are refused without one.
  std::optional<MachineSpec> machine;
  // The job's cutting model is "teeth": G-code F and S (and G93/G94/G95) are read, not
  // ignored, and M3 / M4 set each move's spindle direction (Move::spindle).
  bool teeth = false;
  // The flute count of the job's one "tool" (with "tools", each cutter's own), for the
  // G-code feed per tooth F / (S flutes).
  int flutes = 2;
  // A tool axis below the horizontal (k < 0) is refused as it is read; off when the job
  // has a frame, whose loader judges the axes in the frame (job_loader.h).
  bool axesFromAbove = true;
  // The memory the moves may take, bytes; 0: what the machine has available
  // (base/available_memory.h), checked from a million moves on. See ToolPathFile::addMove.
  double memoryBytes = 0;
  // Keep only the moves that can reach this grid (tools/io/move_window.h); a file read
  // as a stream (streamToolPathFile) keeps every move.
  std::optional<ReadWindow> window;
};

struct ToolPathFile {
  std::string format;  // "cl-text", "apt" or "gcode"
  ToolPath path;
  // moveLines[k]: 1-based line of the file that made path.moves[k] (for an APT
  // statement with continuation lines, its first line).
  std::vector<int64_t> moveLines;
  PathWarnings warnings;
  std::optional<Cutter> cutter;  // APT CUTTER/ statement, when present
  double arcTolerance = 0;       // mm, for G-code arcs (0 when the format has none)
  // A multi-tool file: toolNumbers[k] is the T number (G-code, APT LOADTL) of
  // path.cutters[k], or for APT CUTTER/s without LOADTL, k + 1 (their order).
  std::vector<int64_t> toolNumbers;
  IgnoredWords ignored;
  std::string source;      // the file, for the memory refusal
  double memoryBytes = 0;  // PathFileOptions::memoryBytes
  // With PathFileOptions::window: every move the file made, and the seconds and bytes of
  // the read (report.json path_file).
  size_t movesRead = 0;
  double readSeconds = 0, fileBytes = 0;
  std::vector<MoveWindowFilter::ToolMoves> toolMoves;  // of every move read, by tool index
  std::shared_ptr<MoveWindowFilter> filter;  // PathFileOptions::window, while reading

  // Appends a move from the current location (the last move's end). Never killed for
  // memory: before the moves' arrays grow (doubling: the old and the new are held at
  // once) their next size is checked against the memory available (80 % of it, as every
  // refusal), and a program that outgrows it is refused naming the line it reached.
  void addMove(const Pose& from, const Pose& to, bool rapid, int64_t line);

  // A file read as a stream (streamToolPathFile): the moves go to `takePart` a part of at
  // most `partMoves` at a time, handed over just before the next move is added (so that
  // a reader's changes to the last move are in), and path.moves and moveLines hold the
  // moves of one part only; arcs and rotary motions (which moves index) stay whole.
  std::function<void(ToolPath&)> takePart;
  size_t partMoves = 0;
  size_t movesHandedOver = 0;
  void handOverPart();
};

// Reads `path` in the format of its extension. Throws InputError("file:line", ...).
ToolPathFile readToolPathFile(const std::string& path, const PathFileOptions& options = {});

// Reads `path` as readToolPathFile does, handing its moves to `takePart` in order, at most
// `partMoves` at a time (ToolPathFile::takePart), without holding them all: a file read
// once whole to check it is re-read this way a band at a time (tools/run/
// tiled_simulation.h). Returns the file as read, every move handed over (movesHandedOver).
ToolPathFile streamToolPathFile(const std::string& path, const PathFileOptions& options,
                                size_t partMoves, const std::function<void(ToolPath&)>& takePart);

// The plain CL text reader on a stream or a string (`source` names it in messages).
void readClText(std::istream& in, const std::string& source, ToolPathFile& out,
                bool axesFromAbove = true);
ToolPath parseToolPath(const std::string& text, const std::string& source);

// Adds a warning for every rapid move whose cutter goes below the stock top inside
// the stock's xy box, a crash on the machine. Conservative: the cutter's lowest point
// along the move (exact for a fixed axis, the lower of both ends' for a turning one)
// below stock.max.z while the tip's path there comes within the cutter's horizontal
// reach (R, plus flute length x sin(tilt) for a tilted axis) of the box. Retracts
// straight up the tool axis are not flagged (they leave by the way the cutter is).
// A multi-tool file's rapids are checked with the tool in the spindle
// (path.cutters[move.tool]), others with `cutter`. With `solid` (a stock of any shape,
// `stock` its bounding box), a rapid the box test flags is judged against the solid
// itself: flagged only when a point of the solid higher than the cutter's lowest point
// (the lowest over the part of the move below the box top) lies within the horizontal
// reach of the tip's path there (StockSolid::reachesAbove, exact, not sampled).
// The warning names the stock (`stockName`: "the stock box", "the solid stock
// blank.stl"...), the cutter's lowest point and, for a box, the tip there and the
// depth below the top; for a solid, its highest point within the cutter's reach and
// how far above the cutter's lowest point it is. Every check is against the stock as it
// started: a rapid through material earlier moves removed is flagged all the same.
void warnRapidsIntoStock(ToolPathFile& file, const Cutter& cutter, const Box3& stock,
                         const std::string& source, const StockSolid* solid = nullptr,
                         const std::string& stockName = "the stock box");

// A tool axis read from a file: a vector already unit to round-off (as CAM systems
// print them, 17 digits round-trip) is kept bit for bit, so the sweep's own
// normalisation treats it exactly like a generated axis; others are normalised.
// Throws InputError(where) for a zero or non-finite axis, and with `fromAbove` for one
// below the horizontal.
Vec3 fileAxis(const Vec3& axis, const std::string& where, bool fromAbove = true);

// Parses a number the way every reader does: decimal only (no hex, inf or nan),
// the whole token consumed. Returns false otherwise.
bool parseDecimal(const std::string& token, double& value);

}  // namespace scallop
