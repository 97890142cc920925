// Determinism: the same job gives bit-identical outputs on 1 and 2 threads
// and from one run to the next. heights.gsf and preview.png are compared byte for
// byte; heights.exr by its pixels and every header attribute except DateTime (the
// one field OpenImageIO fills from the clock); report.json with its timings, the
// thread count and the throughput (Mcells/s) removed.
#include <OpenImageIO/imageio.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_harness.h"

namespace scallop::test {
namespace {

// A bull cutter with lead and tilt on short moves, zigzag, over 3 x 2.6 mm at 10 um
// (300 x 260 cells): many segments overlap each cell, so the order in which threads
// finish tiles would show if it leaked into the heights.
constexpr const char* kJob = R"({
  "tool":  {"type": "bull", "radius": 1.0, "corner_radius": 0.3},
  "stock": {"min": [0, 0, -1], "max": [3, 2.6, 0]},
  "grid":  {"spacing": 0.01},
  "path":  {"raster": {"direction": "x", "step_over": 0.35, "depth": 0.2, "lead_deg": 7,
                       "tilt_deg": -3, "zigzag": true, "segment_length": 0.1}}
})";

struct Exr {
  std::vector<float> pixels;
  std::vector<std::string> attributes;  // "name=value", DateTime left out
  int width = 0, height = 0;
};

Exr readExr(const fs::path& file) {
  Exr e;
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return e;
  const OIIO::ImageSpec& spec = in->spec();
  e.width = spec.width;
  e.height = spec.height;
  e.pixels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, e.pixels.data());
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    if (p.name() != "DateTime") e.attributes.push_back(p.name().string() + "=" + p.get_string());
  e.attributes.push_back("channels=" + std::to_string(spec.nchannels));
  e.attributes.push_back("tile=" + std::to_string(spec.tile_width) + "x" +
                         std::to_string(spec.tile_height));
  return e;
}

nlohmann::json reportWithoutClock(const fs::path& file) {
  nlohmann::json r = nlohmann::json::parse(slurp(file));
  r.erase("timings_s");
  r.erase("threads");
  r["measurements"].erase("mcells_per_s");
  return r;
}

class Determinism : public CliFixture {
 protected:
  fs::path simulate(const std::string& name, int threads, const std::string& extra = "") {
    const fs::path out = dir_ / name;
    const CliRun r = run("simulate " + path("job.json") + " -o " + out.string() + " --threads " +
                         std::to_string(threads) + extra);
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }

  void expectSame(const fs::path& a, const fs::path& b, int nx = 300, int ny = 260) {
    SCOPED_TRACE(a.filename().string() + " vs " + b.filename().string());
    const std::string gsfA = slurp(a / "heights.gsf");
    ASSERT_GT(gsfA.size(), size_t(nx) * size_t(ny) * 4u);
    EXPECT_TRUE(gsfA == slurp(b / "heights.gsf")) << "heights.gsf differs";
    const std::string pngA = slurp(a / "preview.png");
    ASSERT_FALSE(pngA.empty());
    EXPECT_TRUE(pngA == slurp(b / "preview.png")) << "preview.png differs";
    const Exr ea = readExr(a / "heights.exr"), eb = readExr(b / "heights.exr");
    ASSERT_EQ(ea.width, nx);
    ASSERT_EQ(ea.height, ny);
    EXPECT_TRUE(ea.pixels == eb.pixels) << "heights.exr pixels differ";
    EXPECT_EQ(ea.attributes, eb.attributes);
    EXPECT_EQ(reportWithoutClock(a / "report.json"), reportWithoutClock(b / "report.json"));
  }
};

TEST_F(Determinism, ExactOutputsAreBitIdenticalAcrossThreadsAndRuns) {
  write("job.json", kJob);
  const fs::path one = simulate("t1", 1), two = simulate("t2", 2), again = simulate("t2b", 2);
  expectSame(one, two);
  expectSame(two, again);
  // The map is not trivial: the cutter went below the stock top.
  const nlohmann::json r = nlohmann::json::parse(slurp(one / "report.json"));
  EXPECT_LT(r["measurements"]["min_height"].get<double>(), -0.19);
}

TEST_F(Determinism, BandedAndStampedOutputsAreBitIdenticalAcrossThreads) {
  write("job.json", kJob);
  expectSame(simulate("b1", 1, " --tile-rows 64"), simulate("b2", 2, " --tile-rows 64"));
  // Stamping is slow at 10 um (it is the baseline): 30 um cells, 100 x 87.
  std::string coarse = kJob;
  coarse.replace(coarse.find("0.01}"), 5, "0.03}");
  write("job.json", coarse);
  expectSame(simulate("s1", 1, " --method stamp"), simulate("s2", 2, " --method stamp"), 100, 87);
}

}  // namespace
}  // namespace scallop::test
