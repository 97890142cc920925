// The G-code interpreter: the modal state of a program (units, distance modes, plane,
// work offset, tool, TCP, canned cycle) and the moves its blocks make, block by block
// (tools/io/gcode_reader.h says what every word does).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "tools/io/gcode_block.h"
#include "tools/io/gcode_groups.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

class GcodeInterpreter {
 public:
  GcodeInterpreter(const std::string& source, const PathFileOptions& options, ToolPathFile& out);

  // Runs one block of line `line`. Returns false once the program has ended (M2, M30):
  // the lines after it are not read.
  bool block(const GcodeBlock& b, int64_t line);
  // Checks the program made moves. Throws InputError.
  void finish();

 private:
  // Where the machine is: X Y Z (the tip with TCP on or on a 3-axis machine, the
  // joints with TCP off, job frame, mm) and the rotary angles (radians).
  struct State {
    Vec3 pos;
    double tilt = 0, spin = 0;
  };
  void selectTool(const GcodeBlock& b, bool change);
  State target(const GcodeBlock& b, bool machineFrame, std::array<bool, 3>& known) const;
  void motion(const GcodeBlock& b, const GcodeGroups& g);
  void home(const GcodeBlock& b, int code);
  void arc(const GcodeBlock& b, const State& to);
  void cycle(const GcodeBlock& b);

  Pose poseOf(const State& s) const;
  // A move to `to`; `arc`, when given, is the path its tip follows (an exact G2/G3).
  void moveTo(const State& to, bool rapid, const ArcMotion* arc = nullptr);
  void ignore(const std::string& word, const std::string& meaning);
  int toolIndex();
  void feeds(const GcodeBlock& b, const GcodeGroups& g);
  double feedPerTooth(int tool) const;

  const std::string& source_;
  const PathFileOptions& options_;
  ToolPathFile& out_;
  std::string where_;
  int64_t line_ = 0, firstMoveLine_ = 0;
  double scale_ = 1;  // mm per file unit
  int motion_ = -1;   // modal motion in tenths (0, 10, 20, 30, cycles 730..890), -1 none
  int plane_ = 17;
  bool absolute_ = true, arcAbsolute_ = false, retractToInitial_ = true, tcp_ = false;
  int workOffset_ = 0;  // 0..5: G54..G59
  State state_;
  std::array<bool, 3> known_{};
  // Tools: the T number selected, the cutter index in the spindle (-1: none yet).
  int64_t selected_ = -1;
  int spindle_ = -1;
  // Canned cycles: the sticky R, Z and Q words (file units) once given.
  double cycleR_ = 0, cycleZ_ = 0, cycleQ_ = 0;
  bool haveR_ = false, haveZ_ = false, haveQ_ = false;
  int percentLines_ = 0;
  // Feeds (the teeth model's feed per tooth, docs/formats.md): the modal F (file units
  // per minute, or per revolution in G95), S (rpm) and feed mode (930, 940, 950).
  double feed_ = 0, spindleRpm_ = 0;
  int feedMode_ = 940;
  // With teeth: 0 until M3 (1, clockwise) or M4 (-1) sets it (Move::spindle).
  int8_t spindleDirection_ = 0;
};

}  // namespace scallop
