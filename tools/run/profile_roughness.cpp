#include "tools/run/profile_roughness.h"

#include "base/input_error.h"

namespace scallop {

Profile lineProfile(const ZMap& map, const std::vector<double>& line, double stepMm,
                    const char* lineField) {
  if (line.size() != 4) throw InputError(lineField, "expected 4 numbers: x0 y0 x1 y1 (mm)");
  return extractProfile(map, line[0], line[1], line[2], line[3], stepMm, lineField);
}

ProfileRoughness profileRoughness(const ZMap& map, const std::vector<double>& line, double stepMm,
                                  double cutoffMm, const char* lineField, const char* cutoffField) {
  ProfileRoughness p{lineProfile(map, line, stepMm, lineField), {}};
  p.roughness = roughness(p.profile, cutoffMm, cutoffField);
  return p;
}

nlohmann::json profileRoughnessDocument(const ProfileRoughness& p) {
  const Profile& l = p.profile;
  const RoughnessStats& r = p.roughness;
  return {{"line_mm", {l.x0, l.y0, l.x1, l.y1}},
          {"step_mm", l.stepMm},
          {"samples", l.height.size()},
          {"cutoff_mm", r.cutoffMm},
          {"sampling_lengths", r.samplingLengths},
          {"evaluation_start_mm", r.evaluationStartMm},
          {"evaluation_length_mm", r.evaluationLengthMm},
          {"Ra_mm", r.ra},
          {"Rq_mm", r.rq},
          {"Rz_mm", r.rz},
          {"Rt_mm", r.rt},
          {"convention",
           "ISO 16610-21 Gaussian mean line (cutoff lc, kernel truncated at +-lc, run-in and "
           "run-out of lc each), up to 5 sampling lengths of lc (ISO 4288), Rz = mean of the "
           "sampling lengths' peak-to-valley; no lambda-s filter"}};
}

}  // namespace scallop
