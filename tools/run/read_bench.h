// B11, the reading benchmark of `scallop bench`: a large plain-linear G-code program
// (B9's kind: ball R1 finishing passes along X 0.1 mm apart, a G1 every 0.05 mm, 4
// decimals; bench_cases.h finishingGcode) is generated into a temporary file, not
// shipped, and read through readToolPathFile as a user's file is: the rate in MB/s and
// in moves/s on one core (the reader is serial).
#pragma once

#include <cstddef>
#include <string>

namespace scallop {

struct ReadBenchResult {
  double width = 0;  // mm, the stock's x side (y is half of it)
  double bytes = 0, seconds = 0;
  size_t moves = 0;
};

// The program over a `width` x width/2 mm stock: 100 mm (about 10^6 moves, 25 MB) by
// default, 20 mm (4 10^4 moves, 1 MB) with `quick`; `area` > 0 chooses the width. The
// faster of two reads counts.
ReadBenchResult runReadBench(bool quick, double area);

}  // namespace scallop
