// G-code reader (.nc, .ngc, .gcode, .tap): milling programs in the ISO / Fanuc /
// LinuxCNC dialect as CAM post-processors write them, 3-axis or 5-axis (table-table
// machines), with one tool or many. docs/formats.md has the table of every word with
// what LinuxCNC and CAMotics do with it.
//
// The reader is three layers: gcode_block.h (the words of a line: comments ( ) and ;,
// block delete '/', '%', O program numbers, N), gcode_interpreter.h (the modal state
// and the moves), gcode_arc.h and gcode_cycles.h (arcs into chords, drilling cycles
// into their moves). What the words do:
//   motion   G0 rapid, G1 linear, G2/G3 arcs (I J K offsets, or absolute with G90.1;
//            R form, R < 0 the long way), helical in G17/G18/G19; G80 cancels a cycle
//   cycles   G73 G81 G82 G83 G84 G85 G86 G88 G89 with G98/G99, R, Z, Q, L and modal
//            repeats: their moves are made and every feed is swept exactly
//   modes    G17-G19, G20/G21 (one unit per file), G90/G91, G90.1/G91.1, G93/G94/G95,
//            G61/G61.1/G64 (G64 P: a warning; the programmed path is followed)
//   offsets  G54-G59 from PathFileOptions::workOffsets (zero by default); G53 moves in
//            the job frame; G28/G30: a rapid to the intermediate point, then the axes
//            named are unknown (home is the machine's; a warning) until a move gives them
//   tools    T selects, M6 changes: with PathFileOptions::tools each move is cut by the
//            tool in the spindle (path.cutters, Move::tool); a T not in tools is an
//            error; without tools, T and M6 are ignored (the job's one tool)
//   machine  A/B/C rotary words (degrees) with PathFileOptions::machine; its tcp_on /
//            tcp_off codes (default G43.4 / G49) switch TCP: on, X Y Z are the tip and
//            the move is PoseCurve::rotary; off, X Y Z are joints and the tip follows
//            the forward kinematics (a move whose angles change is then refused by the
//            sweep, tool_path_sweep.h, until the kernel sweeps curved tips)
//   no geometry  F, S, H, D, G4, G40, G43, G43.4, G49 (without a machine), M0 M1 M3-M5
//            M7-M9; listed in ToolPathFile::ignored (report.json) with their lines.
//            M2/M30 end the program, as a second '%' does: later lines are not read.
//            Other M codes: a warning with the line, ignored.
//   feeds    with the teeth model (PathFileOptions::teeth) F, S and G93/G94/G95 are read:
//            each cutting move's Move::feedPerTooth = F / (S flutes) in G94, F / flutes
//            in G95, 0 in G93 or without S; M3 / M4 set Move::spindle (clockwise /
//            counter-clockwise) for the moves after them.
// Refused with "file:line" and the reason (InputError): G41/G42 (cutter radius
// compensation), G87, G10/G52/G92, other G words, M98/M99 and O-word subprograms, '#'
// parameters, U V W and other letters, a word twice or two of one modal group, mixed
// units, a cutting move or incremental word from an unknown position, rotary words
// without a machine, arcs whose radii differ by more than 0.002 mm, cycles outside G17
// or with Z above R.
#pragma once

#include <iosfwd>
#include <string>

#include "tools/io/tool_path_file.h"

namespace scallop {

void readGcode(std::istream& in, const std::string& source, const PathFileOptions& options,
               ToolPathFile& out);

}  // namespace scallop
