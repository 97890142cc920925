// One block (line) of G-code, lexed into its words: the lexical layer of the G-code
// reader (tools/io/gcode_reader.h), which knows the syntax and nothing of what the
// words do.
//
// A line holds words (a letter and a decimal number, spaces anywhere, either case),
// ( ... ) comments and a ; comment to its end. A '/' first on the line is block delete:
// the line is skipped when block delete is on, read otherwise. A line of '%' alone is a
// program delimiter. "O1000" alone (a program number, Fanuc style) carries no words.
// Refused, naming the line: '#' parameters, '[' expressions, O-word subprograms and
// flow control (O100 sub/call/if..., O<name>), an E straight after a number (an
// exponent, "X1e300": G-code has none), letters scallop does not read (U V W E
// and others), a word twice, a number that is not a finite decimal.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace scallop {

struct GcodeBlock {
  enum class Kind { Empty, Percent, Words };
  Kind kind = Kind::Empty;
  std::array<bool, 26> has{};
  std::array<double, 26> value{};
  std::vector<double> g;  // G words in the order of the line
  std::vector<double> m;  // M words
  bool given(char c) const { return has[size_t(c - 'A')]; }
  double at(char c) const { return value[size_t(c - 'A')]; }
};

// Lexes `line`; `where` ("file:line") names it in InputErrors.
GcodeBlock lexGcodeBlock(const std::string& line, const std::string& where, bool blockDelete);

// A G or M word's number as a code in tenths (G43.4 -> 434, G1 -> 10), or -1 when it
// is not a whole number of tenths in [0, 1000).
int gcodeTenths(double value);

// The canonical text of a word: "G43.4", "G1", "M128" (what the job's machine codes
// are compared with).
std::string gcodeWordText(char letter, double value);

}  // namespace scallop
