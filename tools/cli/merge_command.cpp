#include "tools/cli/merge_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/run/band_files.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"
#include "tools/run/tiled_simulation.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

int runMerge(const MergeArgs& args) {
  const auto tStart = Clock::now();
  if (!fs::is_directory(args.dir)) throw InputError(args.dir, "not a folder");
  // Every band description present, by index. The run is the lowest band's; every
  // other band must carry its fingerprint.
  std::map<int64_t, std::string> sidecars;
  const std::regex name(R"(band-(\d{1,15})\.json)");
  for (const auto& entry : fs::directory_iterator(args.dir)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (std::regex_match(file, m, name)) sidecars[std::stoll(m[1].str())] = entry.path().string();
  }
  if (sidecars.empty())
    throw InputError(args.dir,
                     "no band files (band-K.json) here; write them with `scallop simulate JOB "
                     "-o DIR --bands K:M`");
  const auto& [firstBand, firstPath] = *sidecars.begin();
  const json reference = readBandDescription(firstPath, firstBand);
  const json& run = reference.at("run");
  const std::string fingerprint = reference.at("fingerprint");
  if (fingerprint != runFingerprint(run))
    throw InputError(firstPath, "damaged band description: its fingerprint does not match its run");
  int64_t bands = 0;
  try {
    bands = run.at("bands").get<int64_t>();
    gridFromJson(run.at("grid"));
  } catch (const json::exception& e) {
    throw InputError(firstPath, std::string("damaged band description: ") + e.what());
  }

  // Before anything is written: every band there, of this run, whole in size.
  for (const auto& [b, p] : sidecars)
    if (b >= bands)
      throw InputError(p, fmt::format("band {} of a run with only {} bands (bands 0..{}); it "
                                      "belongs to another job or --tile-rows",
                                      b, bands, bands - 1));
  std::map<int64_t, json> descriptions;
  for (int64_t b = 0; b < bands; ++b) {
    if (!sidecars.count(b))
      throw InputError(bandDescriptionPath(args.dir, b),
                       fmt::format("missing: band {} of {} was not computed (or not to the end); "
                                   "{}",
                                   b, bands, bandCommand(args.dir, b, reference)));
    json doc = readBandDescription(sidecars[b], b);
    if (doc.at("fingerprint") != fingerprint)
      throw InputError(sidecars[b],
                       fmt::format("belongs to another run than {} (fingerprint {}, expected "
                                   "{}: a different job, grid, --tile-rows or scallop version); "
                                   "{}",
                                   fs::path(firstPath).filename().string(),
                                   doc["fingerprint"].get<std::string>(), fingerprint,
                                   bandCommand(args.dir, b, reference)));
    checkBandRawSize(args.dir, b, doc);
    descriptions[b] = std::move(doc);
  }

  // Every band is there: what killed writers of these bands left only takes disk space
  // (band_files.h: removeStaleBandTemporaries spares what may be a live rerun's).
  for (const std::string& leftover : removeStaleBandTemporaries(args.dir, bands))
    std::fprintf(stderr, "scallop: removed %s, left by a run of its band that was killed\n",
                 leftover.c_str());

  // One pass: each band is read, its MD5 verified, and streamed into the outputs, which
  // appear only when all are complete.
  const GridSpec grid = gridFromJson(run.at("grid"));
  BandLayout layout;
  layout.bandRows = run.at("band_rows").get<int64_t>();
  layout.bands = bands;
  TiledOutput output(tiledRunFromBands(run), args.dir);
  double sceneSeconds = 0;
  int threads = 0;
  for (int64_t b = 0; b < bands; ++b) {
    const json& doc = descriptions[b];
    ZMap band(layout.bandGrid(b, grid), 0.0);
    readBandRaw(args.dir, b, doc, band);
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
      "Assemble the bands of `simulate --bands` into one run's outputs.\n"
      "Assemble DIR/band-K.raw files of `simulate --bands K:M` runs into DIR/heights.exr\n"
      "(tiled OpenEXR, float32 Z in mm), heights.gsf (metres), preview.png and report.json,\n"
      "as one `simulate --tiled` run would write them. Every band is checked first: a\n"
      "missing, partial (size) or corrupt (MD5) band, or one of another job, grid or\n"
      "--tile-rows (fingerprint), fails (exit 1) naming it and the command that computes it\n"
      "again; nothing is written then. The band files are left in place; hidden temporaries\n"
      "(.band-K.raw.tmp-*) that killed runs of these bands left are removed.");
  app->add_option("DIR", args->dir, "Folder holding the band files")->required();
  app->add_flag("--json", args->json, "Print report.json on stdout (and nothing else there)");
  return {app, [args]() { return runMerge(*args); }};
}

}  // namespace scallop
