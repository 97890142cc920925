// FNV-1a, 64 bits: the one hash of scallop's heights (the benchmark's and the
// performance guard's heights hashes) and of the keys it hashes (mesh vertices).
// Not for security.
#pragma once

#include <cstdint>
#include <cstring>

namespace scallop {

struct Fnv1a {
  // The offset basis every recorded heights hash was made with
  // (tests/benchmarks/perf-baseline.txt, tests/support/bench_heights.h); FNV publishes
  // 14695981039346656037, but changing it would change every hash on record.
  static constexpr uint64_t kOffsetBasis = 1469598103934665603ull;
  static constexpr uint64_t kPrime = 1099511628211ull;

  uint64_t value = kOffsetBasis;

  // FNV-1a proper: the 8 bytes of `v`, least significant first.
  void addBytesOf(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      value ^= (bits >> (8 * k)) & 0xff;
      value *= kPrime;
    }
  }
  // A whole 64-bit word at a time: a word-wise variant, faster where only equal
  // inputs hashing alike matters.
  void addWord(uint64_t word) { value = (value ^ word) * kPrime; }
  void addWordOf(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    addWord(bits);
  }
};

}  // namespace scallop
