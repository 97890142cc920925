// Job loading: a parsed job (tools/io/job.h) completed with what its files and
// generators give, checked against the memory available, ready to run.
#pragma once

#include <string>

#include "tools/io/job.h"

namespace scallop {

// Reads the design STL, generates the raster or reads the tool-path file (taking the
// cutter from its CUTTER/ when the job has no "tool"), and checks the path. Without
// `checkMemory` a grid too large to hold is accepted (the caller computes it in bands,
// tools/run/tiled_simulation.h). Errors name the job file first, as parseJob's do.
void loadJobInputs(Job& job, bool checkMemory = true);

// parseJob, then loadJobInputs. `arcChords` (the CLI's --arc-chords) reads G-code arcs
// as chords, as the job key "arc_chords" does.
Job loadJob(const std::string& text, const std::string& source, bool checkMemory = true,
            const std::string& pathOverride = "", bool arcChords = false);

// Reads the job file at `path`, then loadJob.
Job loadJobFile(const std::string& path, bool checkMemory = true,
                const std::string& pathOverride = "", bool arcChords = false);

}  // namespace scallop
