// Band files (tools/run/band_files.h) as `scallop merge` sees them after things go
// wrong: a band missing, cut short, corrupt, of another job, or described but without
// its heights. Each must exit 1 naming the band file and the command that computes it
// again, and leave no merged output (temporaries included); rerunning only that band
// completes the map with the same bits.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_harness.h"

namespace fs = std::filesystem;

namespace {

using scallop::test::CliRun;
using scallop::test::slurp;

class BandFiles : public scallop::test::CliFixture {
 protected:
  // 120 x 150 cells, 32-row bands: 5 bands, the last one of 22 rows.
  std::string job(double stepOver = 1.1) {
    return write("job.json", R"({
      "tool":  {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
      "stock": {"min": [0.1, -0.3, -2], "max": [1.3, 1.2, 0]},
      "grid":  {"spacing": 0.01},
      "path":  {"raster": {"direction": "x", "step_over": )" +
                                 std::to_string(stepOver) + R"(, "depth": 0.3, "lead_deg": 5}}
    })")
        .string();
  }
  CliRun bands(const std::string& out, const std::string& range, double stepOver = 1.1) {
    return run("simulate " + job(stepOver) + " -o " + path(out) + " --tile-rows 32 --bands " +
               range);
  }
  void computeAll(const std::string& out) {
    const CliRun r = bands(out, "0:5");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // merge fails with status 1, naming `file` and `--bands K:K+1`, writing nothing.
  void expectRefused(const std::string& out, const std::string& file, int band) {
    const CliRun m = run("merge " + path(out));
    EXPECT_EQ(m.status, 1) << m.err;
    EXPECT_EQ(m.out, "");
    EXPECT_NE(m.err.find(file), std::string::npos) << m.err;
    const std::string again = "--bands " + std::to_string(band) + ":" + std::to_string(band + 1);
    EXPECT_NE(m.err.find(again), std::string::npos) << m.err;
    EXPECT_NE(m.err.find("--tile-rows 32"), std::string::npos) << m.err;
    for (const auto& entry : fs::directory_iterator(path(out))) {
      const std::string name = entry.path().filename().string();
      EXPECT_EQ(name.rfind("band-", 0), 0u) << "left behind: " << name;
    }
  }
  std::string band(const std::string& out, int k, const char* ext) {
    return path(out) + "/band-" + std::to_string(k) + ext;
  }
};

TEST_F(BandFiles, DescriptionCarriesTheRawsSizeMd5AndTheRunsFingerprint) {
  computeAll("a");
  computeAll("b");
  const nlohmann::json d = nlohmann::json::parse(slurp(band("a", 1, ".json")));
  EXPECT_EQ(d["format"], "scallop band 2");
  EXPECT_EQ(d["band"], 1);
  EXPECT_EQ(d["tile_rows"], 32);
  EXPECT_EQ(d["raw"]["bytes"], 120 * 32 * 8);
  EXPECT_EQ(d["raw"]["bytes"].get<uintmax_t>(), fs::file_size(band("a", 1, ".raw")));
  EXPECT_EQ(d["raw"]["md5"].get<std::string>().size(), 32u);
  // Same job: same fingerprint in every band and every run; another job: another.
  const nlohmann::json d4 = nlohmann::json::parse(slurp(band("b", 4, ".json")));
  EXPECT_EQ(d["fingerprint"], d4["fingerprint"]);
  ASSERT_EQ(bands("c", "0:1", 1.2).status, 0);
  EXPECT_NE(nlohmann::json::parse(slurp(band("c", 0, ".json")))["fingerprint"], d["fingerprint"]);
}

TEST_F(BandFiles, MissingDescriptionMeansTheBandIsMissing) {
  computeAll("o");
  // What a task killed after writing the heights but before the description leaves.
  fs::remove(band("o", 2, ".json"));
  expectRefused("o", "band-2.json", 2);
  EXPECT_NE(run("merge " + path("o")).err.find("missing"), std::string::npos);
}

TEST_F(BandFiles, MissingOrTruncatedHeightsAreRefusedBeforeWriting) {
  computeAll("o");
  fs::remove(band("o", 3, ".raw"));
  expectRefused("o", "band-3.raw", 3);
  computeAll("p");
  fs::resize_file(band("p", 0, ".raw"), 1000);
  expectRefused("p", "band-0.raw", 0);
  EXPECT_NE(run("merge " + path("p")).err.find("partial"), std::string::npos);
}

TEST_F(BandFiles, CorruptHeightsFailTheMd5) {
  computeAll("o");
  // The last band: bands 0..3 are already streamed into the outputs when it is read.
  {
    std::fstream f(band("o", 4, ".raw"), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(777);
    f.put('\x5a');
  }
  expectRefused("o", "band-4.raw", 4);
  EXPECT_NE(run("merge " + path("o")).err.find("MD5"), std::string::npos);
}

TEST_F(BandFiles, DamagedDescriptionIsNamed) {
  computeAll("o");
  std::ofstream(band("o", 1, ".json")) << "{\"format\": \"scallop band 2\", \"band\": ";
  const CliRun m = run("merge " + path("o"));
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("band-1.json"), std::string::npos) << m.err;
  EXPECT_FALSE(fs::exists(path("o") + "/heights.exr"));
  // An older format is named as such.
  std::ofstream(band("o", 1, ".json")) << R"({"format": "scallop band 1", "band": 1})";
  const CliRun old = run("merge " + path("o"));
  EXPECT_EQ(old.status, 1);
  EXPECT_NE(old.err.find("scallop band 1"), std::string::npos) << old.err;
}

TEST_F(BandFiles, BandsOfAnotherJobAreRefusedByFingerprint) {
  // Band 3 of a job with another step-over (same grid and layout) in the folder.
  ASSERT_EQ(bands("o", "0:3").status, 0);
  ASSERT_EQ(bands("o", "3:4", 1.3).status, 0);
  ASSERT_EQ(bands("o", "4:5").status, 0);
  expectRefused("o", "band-3.json", 3);
  EXPECT_NE(run("merge " + path("o")).err.find("fingerprint"), std::string::npos);
  // A band beyond the run's count (of a finer layout) is refused too.
  ASSERT_EQ(bands("o", "3:4").status, 0);
  ASSERT_EQ(run("simulate " + job() + " -o " + path("o") + " --tile-rows 16 --bands 9:10").status,
            0);
  const CliRun m = run("merge " + path("o"));
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("band-9.json"), std::string::npos) << m.err;
}

TEST_F(BandFiles, RerunningOnlyTheFailedBandCompletesTheSameMap) {
  computeAll("whole");
  ASSERT_EQ(run("merge " + path("whole")).status, 0);
  computeAll("o");
  fs::remove(band("o", 2, ".json"));
  fs::resize_file(band("o", 2, ".raw"), 10);
  ASSERT_EQ(run("merge " + path("o")).status, 1);
  ASSERT_EQ(bands("o", "2:3").status, 0);
  const CliRun m = run("merge " + path("o"));
  ASSERT_EQ(m.status, 0) << m.err;
  for (const char* f : {"heights.gsf", "preview.png"})
    EXPECT_EQ(slurp(path("o") + "/" + f), slurp(path("whole") + "/" + f)) << f;
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(slurp(band("o", k, ".raw")), slurp(band("whole", k, ".raw")));
}

// What a task killed while it wrote band K leaves (tools/io/atomic_file.h's names).
std::string leftover(const std::string& dir, const std::string& name) {
  const std::string p = dir + "/" + name;
  std::ofstream(p, std::ios::binary) << std::string(1000, '\x7f');
  return p;
}

TEST_F(BandFiles, NextRunOfABandRemovesWhatAKilledRunOfItLeft) {
  computeAll("whole");
  ASSERT_EQ(run("merge " + path("whole")).status, 0);
  fs::create_directories(path("o"));
  const std::string raw2 = leftover(path("o"), ".band-2.raw.tmp-4321-0");
  const std::string json4 = leftover(path("o"), ".band-4.json.tmp-4321-1");
  // Not a band temporary (another output's, or only alike): never touched.
  const std::string exr = leftover(path("o"), ".heights.exr.tmp-4321-2");
  const std::string alike = leftover(path("o"), ".band-02.raw.tmp-4321-3");
  const CliRun first = bands("o", "0:3");
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_FALSE(fs::exists(raw2));
  EXPECT_NE(first.err.find(".band-2.raw.tmp-4321-0"), std::string::npos) << first.err;
  // Band 4 is not this run's: its temporary may be another task's, still writing.
  EXPECT_TRUE(fs::exists(json4));
  ASSERT_EQ(bands("o", "3:5").status, 0);
  EXPECT_FALSE(fs::exists(json4));
  EXPECT_TRUE(fs::exists(exr));
  EXPECT_TRUE(fs::exists(alike));
  const CliRun m = run("merge " + path("o"));
  ASSERT_EQ(m.status, 0) << m.err;
  for (const char* f : {"heights.gsf", "preview.png"})
    EXPECT_EQ(slurp(path("o") + "/" + f), slurp(path("whole") + "/" + f)) << f;
}

TEST_F(BandFiles, MergeRemovesTemporariesNoNewerThanTheirBand) {
  computeAll("whole");
  ASSERT_EQ(run("merge " + path("whole")).status, 0);
  computeAll("o");
  const auto completed = [&](int k) { return fs::last_write_time(band("o", k, ".json")); };
  const std::string stale = leftover(path("o"), ".band-1.raw.tmp-4321-0");
  fs::last_write_time(stale, completed(1) - std::chrono::hours(1));
  const std::string sameTime = leftover(path("o"), ".band-3.json.tmp-4321-1");
  fs::last_write_time(sameTime, completed(3));
  // Written after band 2 was complete: a rerun of band 2 may be writing it now.
  const std::string live = leftover(path("o"), ".band-2.raw.tmp-4321-2");
  fs::last_write_time(live, completed(2) + std::chrono::hours(1));
  // Of a band this run does not have: no description to compare with.
  const std::string beyond = leftover(path("o"), ".band-7.raw.tmp-4321-3");
  fs::last_write_time(beyond, completed(0) - std::chrono::hours(1));
  const CliRun m = run("merge " + path("o"));
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(sameTime));
  EXPECT_NE(m.err.find(".band-1.raw.tmp-4321-0"), std::string::npos) << m.err;
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(beyond));
  for (const char* f : {"heights.gsf", "preview.png"})
    EXPECT_EQ(slurp(path("o") + "/" + f), slurp(path("whole") + "/" + f)) << f;
  // A merge that refuses the folder removes nothing.
  const std::string kept = leftover(path("o"), ".band-0.raw.tmp-4321-4");
  fs::last_write_time(kept, completed(0) - std::chrono::hours(1));
  fs::remove(band("o", 4, ".json"));
  EXPECT_EQ(run("merge " + path("o")).status, 1);
  EXPECT_TRUE(fs::exists(kept));
}

TEST_F(BandFiles, PrintBandsGivesTheLayoutAndComputesNothing) {
  const CliRun r = run("simulate " + job() + " -o " + path("o") + " --tile-rows 32 --print-bands");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "bands=5 band_rows=32 rows=150 columns=120 exr_tile_rows=32\n");
  EXPECT_FALSE(fs::exists(path("o")));
  const CliRun j = run("simulate " + job() + " --print-bands --json");
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(nlohmann::json::parse(j.out)["bands"], 1);
  // A range beyond the layout is bad input naming --bands and the count; nothing written.
  const CliRun bad = bands("o", "4:6");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("--bands"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("5 bands"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(band("o", 4, ".raw")));
  EXPECT_EQ(run("simulate " + job() + " --print-bands --bands 0:1").status, 2);
}

}  // namespace
