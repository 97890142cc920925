// Profile metrology: a height profile along any straight line of a z-map and its
// roughness parameters Ra, Rq, Rz, Rt.
//
// Extraction: samples every `step` mm from (x0, y0) towards (x1, y1) (the end point
// is included when the length is a whole number of steps), each the bilinear
// interpolation of the four surrounding cell centres. Every sample must lie within
// the cell centres' span; a line that leaves it is refused.
//
// Roughness convention (ISO 16610-21 filter, ISO 4287 parameters, ISO 4288 lengths):
//  - the mean line is the Gaussian filter of cutoff lc, weights
//    s(x) = exp(-pi (x / (alpha lc))^2) / (alpha lc), alpha = sqrt(ln 2 / pi)
//    (50 % transmission at wavelength lc), truncated at |x| <= lc (weights below
//    7e-7 of the peak dropped) and normalised to sum 1. The roughness profile is
//    the profile minus its mean line;
//  - the mean line is computed only where the whole truncated kernel fits (no end
//    effects): the first and last lc of the profile are run-in and run-out;
//  - the evaluation length is up to 5 sampling lengths lr = lc (ISO 4288's default),
//    as many as fit, centred in what is left; at least one must fit;
//  - Ra = mean |r|, Rq = sqrt(mean r^2), Rt = max r - min r over the evaluation
//    length, Rz = the mean over the sampling lengths of (max r - min r).
// No short-wave (lambda s) filter is applied: a z-map is already sampled at the grid
// spacing. No separate form removal either: the symmetric Gaussian mean line follows
// a straight trend exactly, so a tilt never reaches the roughness profile.
// Default lc = 0.8 mm, ISO 4288's for 0.1 um < Ra <= 2 um; choose it by that table.
#pragma once

#include <cstdint>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

struct Profile {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the line, mm
  double stepMm = 0;                      // distance between samples
  std::vector<double> height;             // absolute heights, mm; sample k at k * stepMm
  double xAt(int64_t k) const;
  double yAt(int64_t k) const;
};

// stepMm = 0: the grid spacing. Throws InputError(where, ...) for a degenerate line
// or one that leaves the map's cell-centre span.
Profile extractProfile(const ZMap& map, double x0, double y0, double x1, double y1, double stepMm,
                       const char* where);

struct RoughnessStats {
  double cutoffMm = 0;
  int samplingLengths = 0;
  double evaluationStartMm = 0;              // along the profile, from (x0, y0)
  double evaluationLengthMm = 0;             // samplingLengths * cutoff
  int64_t firstSample = 0, sampleCount = 0;  // the evaluation length's samples
  double ra = 0, rq = 0, rz = 0, rt = 0;     // mm
  std::vector<double> roughness;             // r for every profile sample (NaN outside
                                             // the filter's valid part)
};

// Throws InputError(where, ...) when the profile is shorter than 3 lc (run-in,
// one sampling length, run-out) or lc is not positive.
RoughnessStats roughness(const Profile& profile, double cutoffMm, const char* where);

}  // namespace scallop
