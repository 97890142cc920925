// Job loading: a parsed job (tools/io/job.h) completed with what its files and
// generators give, checked against the memory available, ready to run.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "tools/io/job.h"

namespace scallop {

// Reads the design STL, generates the raster or reads the tool-path file (taking the
// cutter from its CUTTER/ when the job has no "tool"), and checks the path. Without
// `checkMemory` a grid too large to hold is accepted (the caller computes it in bands,
// tools/run/tiled_simulation.h). Errors name the job file first, as parseJob's do.
void loadJobInputs(Job& job, bool checkMemory = true);

// A job whose moves a run may drop and re-read from its path file a band at a time
// (streamJobPath): a path file without a frame (whose loader moves the path into it).
bool pathStreams(const Job& job);

// Re-reads the path file of a loaded job (pathStreams) as a stream, handing its moves to
// `takePart` at most `partMoves` at a time, as the job holds them (a job's one "tool"
// cutting a multi-tool file: every move's tool 0). Returns the number of moves read.
// The file was read whole and checked by loadJobInputs with the same options, and its
// reader starts each pass from the same state (modal G-code words, work offsets, the
// machine, the tool in the spindle), so this pass meets no error the first did not;
// a file changed in between is caught by the caller comparing the moves' count.
size_t streamJobPath(const Job& job, size_t partMoves,
                     const std::function<void(ToolPath&)>& takePart);

// Frees the moves of a job whose path streams (job.path.moves and moveLines; its
// cutters, arcs and machine motions stay): what a run computes in bands, re-reading
// the file for each, keeps resident beside a band's scene otherwise.
void releasePathMoves(Job& job);

// parseJob, then loadJobInputs. `arcChords` (the CLI's --arc-chords) reads G-code arcs
// as chords, as the job key "arc_chords" does.
Job loadJob(const std::string& text, const std::string& source, bool checkMemory = true,
            const std::string& pathOverride = "", bool arcChords = false);

// Reads the job file at `path`, then loadJob.
Job loadJobFile(const std::string& path, bool checkMemory = true,
                const std::string& pathOverride = "", bool arcChords = false);

}  // namespace scallop
