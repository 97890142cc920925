#include "tools/cli/merge_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>

#include "sweep/input_error.h"
#include "tools/cli/command.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"
#include "tools/run/tiled_simulation.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json readSidecar(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string(), "cannot open the band description");
  try {
    json doc = json::parse(in);
    if (doc.value("format", "") != "scallop band 1")
      throw InputError(p.string(), "not a scallop band description (format 'scallop band 1')");
    return doc;
  } catch (const json::exception& e) {
    throw InputError(p.string(), std::string("damaged band description: ") + e.what());
  }
}

void readBand(const fs::path& raw, ZMap& band) {
  std::ifstream in(raw, std::ios::binary);
  if (!in)
    throw InputError(raw.string(), "missing: the band's heights were not written (or removed)");
  const std::streamsize bytes = std::streamsize(band.heights().size() * sizeof(double));
  in.read(reinterpret_cast<char*>(band.heights().data()), bytes);
  if (in.gcount() != bytes || in.peek() != std::char_traits<char>::eof())
    throw InputError(raw.string(), fmt::format("expected {} bytes ({} x {} float64 heights)", bytes,
                                               band.nx(), band.ny()));
}

}  // namespace

int runMerge(const MergeArgs& args) {
  const auto tStart = Clock::now();
  if (!fs::is_directory(args.dir)) throw InputError(args.dir, "not a folder");
  // Every band description present, by index; the run comes from the first.
  std::map<int64_t, fs::path> sidecars;
  const std::regex name(R"(band-(\d+)\.json)");
  for (const auto& entry : fs::directory_iterator(args.dir)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (std::regex_match(file, m, name)) sidecars[std::stoll(m[1].str())] = entry.path();
  }
  if (sidecars.empty())
    throw InputError(args.dir,
                     "no band files (band-K.json) here; write them with `scallop simulate JOB "
                     "-o DIR --bands K:M`");
  const json run = readSidecar(sidecars.begin()->second).at("run");
  const int64_t bands = run.at("bands").get<int64_t>();
  for (int64_t b = 0; b < bands; ++b)
    if (!sidecars.count(b))
      throw InputError(
          (fs::path(args.dir) / fmt::format("band-{}.raw", b)).string(),
          fmt::format("missing: band {} of {} was not computed; run `scallop simulate JOB -o {} "
                      "--bands {}:{}` with the same job and --tile-rows",
                      b, bands, args.dir, b, b + 1));
  for (const auto& [b, p] : sidecars)
    if (b >= bands) throw InputError(p.string(), fmt::format("run has only {} bands", bands));

  const GridSpec grid = gridFromJson(run.at("grid"));
  BandLayout layout;
  layout.bandRows = run.at("band_rows").get<int64_t>();
  layout.bands = bands;
  TiledOutput output(run, args.dir);
  double sceneSeconds = 0;
  int threads = 0;
  for (int64_t b = 0; b < bands; ++b) {
    const json doc = readSidecar(sidecars[b]);
    if (doc.at("run") != run || doc.at("band").get<int64_t>() != b)
      throw InputError(sidecars[b].string(),
                       fmt::format("belongs to another run than {} (different job or "
                                   "--tile-rows); compute it again",
                                   sidecars.begin()->second.filename().string()));
    ZMap band(layout.bandGrid(b, grid), 0.0);
    readBand(fs::path(args.dir) / fmt::format("band-{}.raw", b), band);
    const json& stats = doc.at("stats");
    sceneSeconds = std::max(sceneSeconds, stats.value("scene_build_seconds", 0.0));
    threads = std::max(threads, stats.value("threads", 0));
    output.add(band, stats);
  }
  const double total = secondsSince(tStart);
  const json report = output.finish(sceneSeconds, total, threads);
  if (args.json)
    std::fputs((report.dump(2) + "\n").c_str(), stdout);
  else
    std::printf("merged %lld bands: wrote %s/heights.exr, heights.gsf, preview.png, report.json\n",
                (long long)bands, args.dir.c_str());
  return 0;
}

Command addMergeCommand(CLI::App& parent, CommonOptions&) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* app = parent.add_subcommand(
      "merge",
      "Assemble DIR/band-K.raw files of `simulate --bands K:M` runs into DIR/heights.exr\n"
      "(tiled OpenEXR, float32 Z in mm), heights.gsf (metres), preview.png and report.json,\n"
      "as one `simulate --tiled` run would write them. Fails (exit 1) naming a missing band.\n"
      "The band files are left in place.");
  app->add_option("DIR", args->dir, "Folder holding the band files")->required();
  app->add_flag("--json", args->json, "Print report.json on stdout (and nothing else there)");
  return {app, [args]() { return runMerge(*args); }};
}

}  // namespace scallop
