// Band files: what `simulate --bands K:M` leaves in DIR for `scallop merge DIR`.
//
// A band is complete only when DIR/band-K.json exists: it is written last, atomically,
// after DIR/band-K.raw (also atomic), and carries the raw file's size and MD5. So a
// task killed at any point leaves either no band-K.json (the band is missing) or a
// whole, verifiable pair. Every band of one run carries the same fingerprint (an MD5
// of the run description: scallop version, job echo, path-file MD5, grid, layout), so
// bands of another job, grid or --tile-rows in the same folder are refused by name.
//
// band-K.raw: the band's heights, mm, native little-endian float64 in ZMap order (row
// j = 0 is the band's smallest y), nx values a row.
// band-K.json: {"format": "scallop band 2", "fingerprint", "run", "band", "tile_rows",
//               "raw": {"file", "bytes", "md5"}, "stats"}
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

// The fingerprint of a run description: the MD5 of its JSON without "job_source" (the
// job file's name, which may be spelt differently on different machines).
std::string runFingerprint(const nlohmann::json& run);

std::string bandRawPath(const std::string& dir, int64_t band);
std::string bandDescriptionPath(const std::string& dir, int64_t band);

// Writes band-K.raw, then band-K.json; an older band-K.json is removed first, so the
// band counts as missing until both are whole. `tileRows` is the --tile-rows asked for
// (0: the default), kept so that merge can say how to compute a missing band again.
void writeBandFiles(const std::string& dir, int64_t band, const ZMap& map,
                    const nlohmann::json& run, int64_t tileRows, const nlohmann::json& stats);

// Leftovers of killed band writers. band-K.raw and band-K.json are written under hidden
// temporary names (".band-K.raw.tmp-PID-N", atomic_file.h) and renamed when whole; a
// task killed meanwhile (Slurm's time limit or scancel after its grace period, a node
// failure: SIGKILL leaves no chance to clean up) leaves its temporary behind, as large
// as the band. It never counts as a band, but it takes disk space on the shared folder,
// so the next writer of that band and the merge remove it:
//
// removeBandTemporaries: every temporary of bands [first, end), at the start of
// `simulate --bands first:end`. That run is the writer of those bands: it replaces
// band-K.raw and band-K.json whatever is there, so another process writing the same
// band at the same time would already spoil the band (merge's MD5 check says so).
std::vector<std::string> removeBandTemporaries(const std::string& dir, int64_t first, int64_t end);

// removeStaleBandTemporaries: in merge, once bands 0..bands-1 are all there, the
// temporaries of those bands last written no later than the band's band-K.json. A
// writer removes band-K.json before it creates its temporaries and writes it again only
// after renaming them, so such a temporary's writer stopped before that band-K.json was
// written: it was killed. A newer one may be a live rerun of the band and is left alone.
std::vector<std::string> removeStaleBandTemporaries(const std::string& dir, int64_t bands);

// Reads and checks band-K.json (format and band index); throws InputError naming it.
nlohmann::json readBandDescription(const std::string& path, int64_t band);

// Checks that band-K.raw exists with the size its description records (a partial or
// missing file is refused before anything is written).
void checkBandRawSize(const std::string& dir, int64_t band, const nlohmann::json& description);

// Reads band-K.raw into `band` (sized by the caller) and verifies its MD5 against the
// description; throws InputError naming the file when it differs.
void readBandRaw(const std::string& dir, int64_t band, const nlohmann::json& description,
                 ZMap& map);

// "scallop simulate JOB -o DIR [--tile-rows N] --bands K:K+1": the command that
// computes band K again, for messages.
std::string bandCommand(const std::string& dir, int64_t band, const nlohmann::json& description);

}  // namespace scallop
