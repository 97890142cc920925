// The design's normal deviation (analysis/normal_deviation.h) as a run output:
// DIR/deviation.ply and report.json's `design.normal_deviation` section.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace scallop {

struct Job;

// Computes the deviation at every vertex of job.design, writes DIR/deviation.ply
// atomically (not when `outDir` is empty) and returns the section: statistics of the
// vertices with a value (count, min, max, mean, rms, a histogram), the vertices cut
// through, without material and unresolved, and the work done. Prints a summary on
// stderr unless `quiet`.
nlohmann::json normalDeviationReport(const Job& job, const std::string& outDir, bool quiet);

}  // namespace scallop
