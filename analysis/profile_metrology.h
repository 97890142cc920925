// Profile metrology: a height profile along any straight line of a z-map and its
// roughness parameters Ra, Rq, Rz, Rt.
//
// Extraction: samples every `step` mm from (x0, y0) towards (x1, y1) (the end point
// is included when the length is a whole number of steps), each the bilinear
// interpolation of the four surrounding cell centres. Every sample must lie within
// the cell centres' span; a line that leaves it is refused.
//
// Roughness convention (ISO 16610-21 filters, ISO 4287 / 21920-2 parameters, ISO 4288
// lengths), with the filters a RoughnessFilter names:
//  - lambda s (optional, short-wave): the Gaussian smoothing of cutoff ls, same weights as
//    below; a z-map is already sampled at the grid spacing, so the default is none;
//  - lambda c (long-wave): the mean line is the Gaussian filter of cutoff lc, weights
//    s(x) = exp(-pi (x / (alpha lc))^2) / (alpha lc), alpha = sqrt(ln 2 / pi)
//    (50 % transmission at wavelength lc), truncated at |x| <= lc (weights below
//    7e-7 of the peak dropped) and normalised to sum 1. The roughness profile is
//    the (ls-smoothed) profile minus its mean line; each filter is computed only where
//    its whole kernel fits (no end effects): run-in and run-out of lc (+ ls) each;
//  - the evaluation length is up to 5 sampling lengths lr = lc (ISO 4288's default),
//    as many as fit, centred in what is left; at least one must fit;
//  - unfiltered (lc = 0): the primary profile less its least-squares line, evaluated
//    over its whole length as one sampling length (Rz = Rt): what a ruler on the
//    marks measures, e.g. feed marks that a 0.8 mm cutoff would attenuate;
//  - Ra = mean |r|, Rq = sqrt(mean r^2), Rt = max r - min r over the evaluation
//    length, Rz = the mean over the sampling lengths of (max r - min r);
//  - Rsm, the mean width of the profile elements (ISO 4287 4.3.1, 21920-2): an element
//    is a peak (r rising above +10 % of Rz) and the valley next to it (r below -10 % of
//    Rz); elements are delimited by the upward crossings of the mean line (linearly
//    interpolated) that follow a valley and precede a peak, and one narrower than 1 % of
//    the sampling length is merged with the next (unfiltered, the sampling length is the
//    evaluation length, as ISO 4287 has it for the primary profile: use a line a few
//    dozen marks long). Rsm is the mean distance between
//    consecutive delimiters over the evaluation length; NaN when fewer than two.
// No separate form removal: the symmetric Gaussian mean line follows a straight trend
// exactly, so a tilt never reaches the roughness profile.
// Default lc = 0.8 mm, ISO 4288's for 0.1 um < Ra <= 2 um; choose it by that table.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
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

// Which filters make the roughness profile (the convention above).
struct RoughnessFilter {
  double cutoffMm = 0.8;  // lc, mm; 0: no long-wave filter (the primary profile)
  double lambdaSMm = 0;   // ls, mm; 0: no short-wave filter
  // How reports name it, e.g. "ISO 16610-21 Gaussian, lc 0.8 mm, no ls".
  std::string name() const;
};

struct RoughnessStats {
  RoughnessFilter filter;
  double cutoffMm = 0;  // lc (0 unfiltered)
  double samplingLengthMm = 0;
  int samplingLengths = 0;
  double evaluationStartMm = 0;              // along the profile, from (x0, y0)
  double evaluationLengthMm = 0;             // samplingLengths * cutoff
  int64_t firstSample = 0, sampleCount = 0;  // the evaluation length's samples
  double ra = 0, rq = 0, rz = 0, rt = 0;     // mm
  double rsm = NAN;                          // mm; NaN: fewer than two element bounds
  std::vector<double> roughness;             // r for every profile sample (NaN outside
                                             // the filter's valid part)
};

// Throws InputError(where, ...) when the profile is shorter than 3 lc + 2 ls (run-in, one
// sampling length, run-out: the message says how long it is and what it needs), when lc
// is negative, or ls is not below lc / 2 or not at least two sample steps.
RoughnessStats roughness(const Profile& profile, const RoughnessFilter& filter, const char* where);
// The Gaussian filter of cutoff `cutoffMm` alone (no ls).
RoughnessStats roughness(const Profile& profile, double cutoffMm, const char* where);

}  // namespace scallop
