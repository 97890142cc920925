// What each libFuzzer target (NAME_fuzz, tests/fuzz/fuzz_driver.cpp) feeds its bytes to, shared
// with tests/tools/io/fuzz_regression_test.cpp, which replays the seed corpus and every
// saved finding (tests/fuzz/regressions/NAME/*) through the same functions in the
// normal test suite.
//
// Contract: given any bytes a reader returns or throws scallop::InputError. Any other
// exception, a crash, a sanitizer report, a hang (-timeout) or a memory blow-up
// (-rss_limit_mb) is a finding.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "raycast/simulation.h"
#include "sweep/cutter.h"
#include "tools/io/apt_reader.h"
#include "tools/io/gcode_reader.h"
#include "tools/io/height_images.h"
#include "tools/io/job.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/job_loader.h"

namespace scallop::fuzz {

// Overwrites one temporary file per process and suffix with `bytes`; returns its path.
inline std::string writeTemp(const std::string& bytes, const std::string& suffix) {
  const char* dir = std::getenv("TMPDIR");
  const std::string path =
      std::string(dir ? dir : "/tmp") + "/scallop-fuzz-" + std::to_string(::getpid()) + suffix;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();  // the harness itself is broken, not the reader
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) std::abort();
  std::fclose(f);
  return path;
}

// A job file, parsed with the memory check on, as `scallop simulate JOB.json` does (a
// raster job also builds its tool path).
inline void fuzzJob(const std::string& bytes) {
  loadJob(bytes, "fuzz.json", true);
}

// An STL surface: binary or ASCII, then the welding and validation of readStl.
inline void fuzzStl(const std::string& bytes) {
  readStl(writeTemp(bytes, ".stl"));
}

// Plain cutter-location text (tools/io/tool_path_file.h).
inline void fuzzToolPath(const std::string& bytes) {
  parseToolPath(bytes, "fuzz.txt");
}

// APT / CL data (tools/io/apt_reader.h).
inline void fuzzApt(const std::string& bytes) {
  std::istringstream in(bytes);
  ToolPathFile out;
  readApt(in, "fuzz.apt", out);
}

// G-code, with arcs at the default chord tolerance (tools/io/gcode_reader.h).
inline void fuzzGcode(const std::string& bytes) {
  std::istringstream in(bytes);
  ToolPathFile out;
  readGcode(in, "fuzz.nc", PathFileOptions(), out);
}

// A Gwyddion Simple Field height map (`scallop stats`, `export`).
inline void fuzzGsf(const std::string& bytes) {
  readHeightsGsf(writeTemp(bytes, ".gsf"));
}

// Cutter locations read *and simulated* (sweep, Embree scene, exact cast) on a fixed
// 6 x 6 grid of 0.25 mm cells, so hostile coordinates (huge, tiny, degenerate axes,
// zero-length moves) reach the geometry, where overflow and float-to-integer
// conversions would be undefined behaviour. Like `scallop simulate`, it refuses tips
// beyond 1 km first (checkPathMagnitudes).
inline void fuzzSimulateCl(const std::string& bytes) {
  const ToolPath path = parseToolPath(bytes, "fuzz.txt");
  checkPathMagnitudes(path, {}, "fuzz.txt");  // as loadJobInputs does for every path file
  // Runs must stay well under the 10 s timeout with sanitizers: at most 16 moves, and
  // turning axes subdivided to 0.01 mm, not 1e-4 (three 90-degree turns make 22,000
  // segments at 1e-4 mm, 5 s even without sanitizers: real work, not a hang).
  if (path.moves.size() > 16) return;
  static const Cutter cutter = Cutter::make(CutterType::Bull, 0.5, 0.2);
  const Box3 stock({0, 0, -1}, {1.5, 1.5, 0});
  SimulationOptions options;
  simulate(cutter, path, stock, gridCovering(0, 0, 1.5, 1.5, 0.25), options);
}

// Target name (the NAME of NAME_fuzz and of its corpus folder) -> function.
inline const std::map<std::string, std::function<void(const std::string&)>>& targets() {
  static const std::map<std::string, std::function<void(const std::string&)>> all = {
      {"job", fuzzJob},
      {"stl", fuzzStl},
      {"toolpath", fuzzToolPath},
      {"gsf", fuzzGsf},
      {"simulate_cl", fuzzSimulateCl},
      {"apt", fuzzApt},
      {"gcode", fuzzGcode}};
  return all;
}

}  // namespace scallop::fuzz
