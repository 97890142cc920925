// Band files (band_files.h): written by `simulate --bands`, checked and read by merge.
#include "tools/run/band_files.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <system_error>

#include "base/input_error.h"
#include "tools/io/atomic_file.h"
#include "tools/io/md5.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "scallop band 2";

std::string heightsMd5(const ZMap& map) {
  Md5 md5;
  md5.update(map.heights().data(), map.heights().size() * sizeof(double));
  return md5.hexDigest();
}

struct BandTemporary {
  std::string path;
  int64_t band = 0;
};

// The hidden temporaries of band files in `dir` (none if it cannot be read).
std::vector<BandTemporary> findBandTemporaries(const std::string& dir) {
  std::vector<BandTemporary> found;
  const std::regex candidate(R"(\.band-(\d{1,15})\.(raw|json)\.tmp-.*)");
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    std::smatch m;
    if (!std::regex_match(name, m, candidate)) continue;
    const int64_t band = std::stoll(m[1].str());
    // The exact name AtomicFile gives band K's file (this also rejects "band-02").
    const std::string file =
        fs::path(m[2] == "raw" ? bandRawPath(dir, band) : bandDescriptionPath(dir, band))
            .filename()
            .string();
    if (isTemporaryNameOf(name, file)) found.push_back({it->path().string(), band});
  }
  return found;
}

bool removeFile(const std::string& path) {
  std::error_code error;
  return fs::remove(path, error) && !error;
}

}  // namespace

std::string runFingerprint(const json& run) {
  json key = run;
  key.erase("job_source");
  return md5Hex(key.dump());
}

std::string bandRawPath(const std::string& dir, int64_t band) {
  return (fs::path(dir) / fmt::format("band-{}.raw", band)).string();
}

std::string bandDescriptionPath(const std::string& dir, int64_t band) {
  return (fs::path(dir) / fmt::format("band-{}.json", band)).string();
}

void writeBandFiles(const std::string& dir, int64_t band, const ZMap& map, const json& run,
                    int64_t tileRows, const json& stats) {
  const std::string raw = bandRawPath(dir, band), side = bandDescriptionPath(dir, band);
  // The old description goes first: from here on the band is missing until it is whole.
  std::error_code ignored;
  fs::remove(side, ignored);
  const size_t bytes = map.heights().size() * sizeof(double);
  writeStreamAtomically(raw, "the band", [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(map.heights().data()), std::streamsize(bytes));
  });
  const json doc = {
      {"format", kFormat},
      {"fingerprint", runFingerprint(run)},
      {"run", run},
      {"band", band},
      {"tile_rows", tileRows},
      {"raw",
       {{"file", fs::path(raw).filename().string()}, {"bytes", bytes}, {"md5", heightsMd5(map)}}},
      {"stats", stats}};
  writeTextAtomically(side, doc.dump(1) + "\n", "the band description");
}

std::vector<std::string> removeBandTemporaries(const std::string& dir, int64_t first, int64_t end) {
  std::vector<std::string> removed;
  for (const BandTemporary& t : findBandTemporaries(dir))
    if (t.band >= first && t.band < end && removeFile(t.path)) removed.push_back(t.path);
  return removed;
}

std::vector<std::string> removeStaleBandTemporaries(const std::string& dir, int64_t bands) {
  std::vector<std::string> removed;
  for (const BandTemporary& t : findBandTemporaries(dir)) {
    if (t.band >= bands) continue;
    std::error_code tempError, bandError;
    const fs::file_time_type written = fs::last_write_time(t.path, tempError);
    const fs::file_time_type complete =
        fs::last_write_time(bandDescriptionPath(dir, t.band), bandError);
    // "No later than" rather than "before": file systems with whole-second times.
    if (tempError || bandError || written > complete) continue;
    if (removeFile(t.path)) removed.push_back(t.path);
  }
  return removed;
}

json readBandDescription(const std::string& path, int64_t band) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the band description");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(path,
                     std::string("damaged band description (compute the band again): ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("format") || !doc["format"].is_string())
    throw InputError(path, fmt::format("not a scallop band description (format '{}')", kFormat));
  if (doc["format"] != kFormat)
    throw InputError(path, fmt::format("band format '{}', expected '{}' (written by another "
                                       "scallop version; compute the band again)",
                                       doc["format"].get<std::string>(), kFormat));
  try {
    const bool complete = doc.at("run").is_object() && doc.at("fingerprint").is_string() &&
                          doc.at("raw").at("md5").is_string() &&
                          doc.at("raw").at("bytes").is_number_unsigned() &&
                          doc.at("stats").is_object();
    if (!complete) throw InputError(path, "damaged band description: a field has the wrong type");
    if (doc.at("band").get<int64_t>() != band)
      throw InputError(path, fmt::format("describes band {}, expected band {} (renamed?)",
                                         doc["band"].get<int64_t>(), band));
  } catch (const json::exception& e) {
    throw InputError(path, std::string("damaged band description: ") + e.what());
  }
  return doc;
}

void checkBandRawSize(const std::string& dir, int64_t band, const json& description) {
  const std::string raw = bandRawPath(dir, band);
  const uintmax_t expected = description["raw"]["bytes"].get<uintmax_t>();
  std::error_code error;
  const uintmax_t size = fs::file_size(raw, error);
  if (error)
    throw InputError(raw, fmt::format("missing: the band's heights are not there ({}); {}",
                                      error.message(), bandCommand(dir, band, description)));
  if (size != expected)
    throw InputError(raw, fmt::format("partial or damaged: {} bytes, band-{}.json expects {}; {}",
                                      size, band, expected, bandCommand(dir, band, description)));
}

void readBandRaw(const std::string& dir, int64_t band, const json& description, ZMap& map) {
  const std::string raw = bandRawPath(dir, band);
  const std::streamsize bytes = std::streamsize(map.heights().size() * sizeof(double));
  if (uintmax_t(bytes) != description["raw"]["bytes"].get<uintmax_t>())
    throw InputError(bandDescriptionPath(dir, band),
                     fmt::format("records {} bytes for a band of {} x {} float64 heights",
                                 description["raw"]["bytes"].get<uintmax_t>(), map.nx(), map.ny()));
  std::ifstream in(raw, std::ios::binary);
  if (!in) throw InputError(raw, "cannot open the band's heights");
  in.read(reinterpret_cast<char*>(map.heights().data()), bytes);
  if (in.gcount() != bytes || in.peek() != std::char_traits<char>::eof())
    throw InputError(raw, fmt::format("partial or damaged: expected {} bytes; {}", bytes,
                                      bandCommand(dir, band, description)));
  const std::string md5 = heightsMd5(map), expected = description["raw"]["md5"];
  if (md5 != expected)
    throw InputError(raw, fmt::format("corrupt: MD5 {}, band-{}.json records {}; {}", md5, band,
                                      expected, bandCommand(dir, band, description)));
}

std::string bandCommand(const std::string& dir, int64_t band, const json& description) {
  const json& run = description.at("run");
  const std::string source = run.value("job_source", "");
  const int64_t tileRows = description.value("tile_rows", int64_t(0));
  return fmt::format("compute it again with `scallop simulate {}-o {}{} --bands {}:{}`",
                     source == "built-in default job" || source.empty() ? "" : source + " ", dir,
                     tileRows > 0 ? fmt::format(" --tile-rows {}", tileRows) : "", band, band + 1);
}

}  // namespace scallop
