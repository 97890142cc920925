#include "tools/run/profile_roughness.h"

#include <cmath>

#include "base/input_error.h"

namespace scallop {

Profile lineProfile(const ZMap& map, const std::vector<double>& line, double stepMm,
                    const char* lineField) {
  if (line.size() != 4) throw InputError(lineField, "expected 4 numbers: x0 y0 x1 y1 (mm)");
  return extractProfile(map, line[0], line[1], line[2], line[3], stepMm, lineField);
}

ProfileRoughness profileRoughness(const ZMap& map, const std::vector<double>& line, double stepMm,
                                  const RoughnessFilter& filter, const char* lineField,
                                  const char* filterField) {
  ProfileRoughness p{lineProfile(map, line, stepMm, lineField), {}};
  p.roughness = roughness(p.profile, filter, filterField);
  return p;
}

nlohmann::json profileRoughnessDocument(const ProfileRoughness& p) {
  const Profile& l = p.profile;
  const RoughnessStats& r = p.roughness;
  return {{"line_mm", {l.x0, l.y0, l.x1, l.y1}},
          {"step_mm", l.stepMm},
          {"samples", l.height.size()},
          {"filter", r.filter.name()},
          {"cutoff_mm", r.cutoffMm},
          {"lambda_s_mm", r.filter.lambdaSMm},
          {"sampling_length_mm", r.samplingLengthMm},
          {"sampling_lengths", r.samplingLengths},
          {"evaluation_start_mm", r.evaluationStartMm},
          {"evaluation_length_mm", r.evaluationLengthMm},
          {"Ra_mm", r.ra},
          {"Rq_mm", r.rq},
          {"Rz_mm", r.rz},
          {"Rt_mm", r.rt},
          {"Rsm_mm", std::isfinite(r.rsm) ? nlohmann::json(r.rsm) : nlohmann::json(nullptr)},
          {"convention",
           "ISO 16610-21 Gaussian filters (kernels truncated at +-cutoff, run-in and run-out of "
           "lc + ls each; lc = 0: unfiltered, the least-squares line removed, one sampling "
           "length), up to 5 sampling lengths of lc (ISO 4288), Rz = mean of the sampling "
           "lengths' peak-to-valley, Rsm (ISO 4287) with height discrimination 10 % of Rz and "
           "width discrimination 1 % of the sampling length"}};
}

}  // namespace scallop
