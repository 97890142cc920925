// Resource guards: a path whose culling scene cannot fit in memory is refused
// before anything is built, naming the bytes; and a tool-path file is read as a stream,
// so reading it costs memory per move, not per byte of text.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "tests/sanitizer.h"
#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tests/support/short_moves_job.h"
#include "tools/io/job.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/memory_limits.h"

namespace scallop {
namespace {

// Short 3-axis moves of a ball R = 1 cutting 0.2 mm deep, as in the 1e6-move
// measurement of checkSceneFitsMemory (estimated ~5.4 KB of scene per move: 20 tiles,
// since moves shorter than R get at most ~16 tiles, see cullingTileSide).
Job shortMoves(size_t n) {
  return test::shortMovesJob(n, 0.1, "guard.json");
}

TEST(ResourceGuard, SceneLargerThanMemoryIsRefusedBeforeBuilding) {
  // Enough moves that even the estimate's per-move floor exceeds what is available.
  const double available = availableMemoryBytes();
  const size_t n = size_t(std::ceil(available / 4000));
  try {
    checkSceneFitsMemory(shortMoves(n));
    FAIL() << n << " moves were accepted with " << available << " bytes available";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("guard.json: path"), std::string::npos) << what;
    EXPECT_NE(what.find(std::to_string(n) + " cutting moves"), std::string::npos) << what;
    EXPECT_NE(what.find(" bytes"), std::string::npos) << what;
  }
  // A hundredth of that is fine (the estimate is linear in the moves).
  EXPECT_NO_THROW(checkSceneFitsMemory(shortMoves(n / 100)));
}

// The same for a 5-axis path whose axis turns inside every move (one primitive each):
// a million and more such moves over a large map are refused up front, naming the
// bytes, rather than built until the kernel's out-of-memory killer stops them.
TEST(ResourceGuard, TurningMovesLargerThanMemoryAreRefusedBeforeBuilding) {
  Job job = shortMoves(0);
  const double available = availableMemoryBytes();
  const size_t n = std::max<size_t>(1000000, size_t(std::ceil(available / 4000)));
  Move m;
  m.from = {{1, 1, -0.2}, normalize(Vec3{0.1, 0, 1})};
  m.to = {{1.05, 1, -0.2}, normalize(Vec3{0.11, 0, 1})};
  job.path.moves.assign(n, m);
  try {
    checkSceneFitsMemory(job);
    FAIL() << n << " turning moves were accepted with " << available << " bytes available";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(std::to_string(n) + " cutting moves"), std::string::npos) << what;
    EXPECT_NE(what.find(" bytes"), std::string::npos) << what;
  }
}

TEST(ResourceGuard, MovesAboveTheStockCostNoScene) {
  Job job = shortMoves(size_t(std::ceil(availableMemoryBytes() / 8000)));
  for (Move& m : job.path.moves) m.from.tip.z = m.to.tip.z = 100;  // far above the top
  EXPECT_NO_THROW(checkSceneFitsMemory(job));
}

long statusKb(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string key;
  long kb = -1;
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(field, 0) == 0) kb = std::stol(line.substr(std::string(field).size()));
  return kb;
}

TEST(ResourceGuard, ToolPathFilesAreReadAsAStream) {
#if SCALLOP_UNDER_ASAN
  // ASan's redzones and its quarantine of freed blocks (the vector's old buffers)
  // change the peak; the measurement belongs to the normal build.
  GTEST_SKIP() << "peak memory is not meaningful under AddressSanitizer";
#endif
  // 1e6 moves of 3-axis CL text (~21 MB). In a child process, so that the peak resident
  // size (VmHWM) measures this read only: it must grow by less than 400 bytes a move
  // (a Move is 104 bytes, its file line 8, vectors at most double), i.e. the ~21 bytes
  // of text per move are never all held, let alone copied.
  const std::string file =
      (test::fs::temp_directory_path() / ("scallop-stream-" + std::to_string(::getpid()) + ".txt"))
          .string();
  constexpr int kMoves = 1000000;
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    for (int k = 0; k <= kMoves; ++k)
      std::fprintf(f, "%.4f %.4f %.4f\n", (k % 1000) * 0.01, (k / 1000) * 0.05,
                   -0.2 - 0.01 * (k % 7));
    std::fclose(f);
  }
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const long before = statusKb("VmRSS:");
    const ToolPathFile read = readToolPathFile(file);
    const long peak = statusKb("VmHWM:");
    const long grown[2] = {peak - before, long(read.path.moves.size())};
    (void)!::write(fds[1], grown, sizeof grown);
    ::_exit(0);
  }
  long grown[2] = {0, 0};
  const ssize_t got = ::read(fds[0], grown, sizeof grown);
  ::waitpid(pid, nullptr, 0);
  ::close(fds[0]);
  ::close(fds[1]);
  std::remove(file.c_str());
  ASSERT_EQ(got, ssize_t(sizeof grown));
  ASSERT_EQ(grown[1], kMoves);
  const double bytesPerMove = double(grown[0]) * 1024 / kMoves;
  RecordProperty("bytes_per_move", std::to_string(bytesPerMove));
  EXPECT_LT(bytesPerMove, 400) << grown[0] << " KB for " << kMoves << " moves";
  std::printf("reading 1e6 CL moves: peak resident size grew by %.0f bytes a move\n", bytesPerMove);
}

// A program whose moves outgrow the memory is refused as it is read, naming the line
// it reached (never killed): here with 200 kB allowed.
TEST(ResourceGuard, AProgramThatOutgrowsTheMemoryIsRefusedAsItIsRead) {
  const std::string file =
      (test::fs::temp_directory_path() / ("scallop-grow-" + std::to_string(::getpid()) + ".txt"))
          .string();
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    for (int k = 0; k <= 5000; ++k) std::fprintf(f, "%d 0 -0.1\n", k);
    std::fclose(f);
  }
  PathFileOptions options;
  options.memoryBytes = 2e5;
  const std::string message = inputErrorMessage([&] { readToolPathFile(file, options); });
  EXPECT_NE(message.find(file + ":"), std::string::npos) << message;
  EXPECT_NE(message.find("do not fit in memory"), std::string::npos) << message;
  // The refusal comes at the first growth past the limit: the moves' array full at n
  // (a power of two) with 3 n (Move + its line) above 80 % of the memory, on the line of
  // move n + 1 (line 1 is the start location).
  size_t n = 1;
  while (3.0 * double(n) * double(sizeof(Move) + sizeof(int64_t)) <= 0.8 * 2e5) n *= 2;
  EXPECT_NE(message.find(":" + std::to_string(n + 2) + ":"), std::string::npos)
      << n << " " << message;
  options.memoryBytes = 1e7;
  EXPECT_EQ(readToolPathFile(file, options).path.moves.size(), 5000u);
  std::remove(file.c_str());
}

}  // namespace
}  // namespace scallop
