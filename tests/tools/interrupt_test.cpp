// Ctrl-C (SIGINT) during a long `scallop simulate`: the run stops within 2 s with exit
// status 130 and "scallop: interrupted", and the output folder holds no height image,
// report or temporary file (tools/cli/interrupt.h), both for the in-memory and the banded
// (--tiled, streamed writers) paths. Also the in-process mechanism: an Interrupted
// thrown by the progress callback leaves the parallel tile loop as an exception.
#include "tools/cli/interrupt.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "raycast/cell_tiles.h"
#include "tests/tools/cli_harness.h"
#include "tools/cli/progress.h"

namespace scallop::test {
namespace {

using Clock = std::chrono::steady_clock;

// The README's default job on a 6667 x 6667 grid with 80 passes: ~10 s on 2 cores.
constexpr const char* kSlowJob = R"({
  "tool":  {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
  "stock": {"min": [0, 0, -5], "max": [20, 20, 0]},
  "grid":  {"spacing": 0.003},
  "path":  {"raster": {"direction": "x", "step_over": 0.25, "depth": 0.5, "lead_deg": 5}}
})";

class InterruptTest : public CliFixture {
 protected:
  // Starts `scallop simulate slow.json -o out EXTRA...`, sends SIGINT `delay` after it
  // started computing, and keeps the wait status and the seconds from signal to exit.
  void interruptAfter(std::chrono::milliseconds delay, std::vector<std::string> extra) {
    const fs::path job = write("slow.json", kSlowJob);
    std::vector<std::string> args = {SCALLOP_BINARY, "simulate",  job.string(), "-o",
                                     path("out"),    "--threads", "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string errPath = path("stderr.txt");
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const int fd = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, STDERR_FILENO);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, STDOUT_FILENO);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    // Wait for the line simulate prints when it starts computing (Ctrl-C before that,
    // while nothing polls, kills the process at once, which is fine but not tested here).
    const auto started = Clock::now();
    while (slurp(errPath).find("cutting moves") == std::string::npos &&
           Clock::now() - started < std::chrono::seconds(60))
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::this_thread::sleep_for(delay);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "the job ended before the signal";
    const auto signalled = Clock::now();
    ASSERT_EQ(::kill(pid, SIGINT), 0);
    pid_t done = 0;
    while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 &&
           Clock::now() - signalled < std::chrono::seconds(20))
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (done == 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      FAIL() << "still running 20 s after SIGINT";
    }
    stopSeconds_ = std::chrono::duration<double>(Clock::now() - signalled).count();
    status_ = status;
    err_ = slurp(errPath);
  }

  void expectCleanStop() {
    ASSERT_TRUE(WIFEXITED(status_)) << "killed by a signal instead of exiting";
    EXPECT_EQ(WEXITSTATUS(status_), 130) << err_;
    EXPECT_NE(err_.find("scallop: interrupted"), std::string::npos) << err_;
    EXPECT_LT(stopSeconds_, 2.0);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(path("out")))
      left.push_back(entry.path().filename().string());
    EXPECT_TRUE(left.empty()) << "left behind: " << left.front();
  }

  int status_ = 0;
  double stopSeconds_ = 0;
  std::string err_;
};

TEST_F(InterruptTest, SigintStopsInMemoryRunPromptlyWithNoOutputs) {
  interruptAfter(std::chrono::milliseconds(700), {});
  expectCleanStop();
}

TEST_F(InterruptTest, SigintStopsBandedRunWithNoTemporaryFiles) {
  // Bands of 256 rows: the streamed EXR and GSF are open (as temporaries) when it stops.
  interruptAfter(std::chrono::milliseconds(700), {"--tile-rows", "256"});
  expectCleanStop();
}

TEST(InterruptFlagTest, ProgressCallbackStopsTheParallelTileLoop) {
  const GridSpec grid = gridCovering(0, 0, 10, 10, 0.01);  // 1000 x 1000 cells, 16 x 16 tiles
  std::atomic<int64_t> tilesRun{0};
  ProgressBar bar("test");
  setInterrupted(false);
  auto work = [&](int64_t, int64_t, int64_t, int64_t) -> uint64_t {
    if (tilesRun.fetch_add(1) == 10) setInterrupted(true);
    return 1;
  };
  EXPECT_THROW(forEachCellTile(
                   grid, 64, [&](int64_t done, int64_t total) { bar.update(done, total); }, work),
               Interrupted);
  setInterrupted(false);
  // TBB cancels the remaining tiles: far fewer than all 256 ran.
  EXPECT_LT(tilesRun.load(), 256);
  // With the flag clear the same loop runs every tile.
  tilesRun = 0;
  EXPECT_EQ(forEachCellTile(
                grid, 64, [&](int64_t done, int64_t total) { bar.update(done, total); },
                [&](int64_t, int64_t, int64_t, int64_t) -> uint64_t { return 1; }),
            256u);
}

}  // namespace
}  // namespace scallop::test
