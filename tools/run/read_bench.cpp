#include "tools/run/read_bench.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "sweep/cutter.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/bench_cases.h"
#include "tools/run/stopwatch.h"

namespace scallop {

ReadBenchResult runReadBench(bool quick, double area) {
  namespace fs = std::filesystem;
  ReadBenchResult r;
  r.width = area > 0 ? area : quick ? 20.0 : 100.0;
  Box3 stock;
  stock.extend({0, 0, -5});
  stock.extend({r.width, 0.5 * r.width, 0});
  const std::string text =
      finishingGcode(Cutter::make(CutterType::Ball, 1), stock, 0.1, 0.05);
  const fs::path file =
      fs::temp_directory_path() / ("scallop-b11-" + std::to_string(::getpid()) + ".nc");
  {
    std::ofstream out(file, std::ios::binary);
    out << text;
  }
  r.bytes = double(text.size());
  r.seconds = HUGE_VAL;
  try {
    for (int run = 0; run < 2; ++run) {
      const auto t0 = Clock::now();
      const ToolPathFile read = readToolPathFile(file.string());
      r.seconds = std::min(r.seconds, secondsSince(t0));
      r.moves = read.path.moves.size();
    }
  } catch (...) {
    fs::remove(file);
    throw;
  }
  fs::remove(file);
  return r;
}

}  // namespace scallop
