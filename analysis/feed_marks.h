// Feed marks measured on a height profile (report.json "feed_marks", docs/teeth.md):
// the peak-to-valley of the heights and the mean spacing of the marks.
//
// Spacing from the valleys (the marks' lowest points, where each tooth passed): the
// profile's turning points are found with a hysteresis of `hysteresis` x PV (a minimum
// counts once the profile has fallen at least that much to it from the last maximum
// and risen that much after it, so a profile's ends and ripples shallower than that
// are not marks), each valley is refined by the parabola through its sample and its
// two neighbours, and the mean spacing is (last - first) / (valleys - 1). Valleys, not
// peaks: a mark's bottom is a smooth arc that the parabola fits, its cusps are sharp.
// The heights are used as given (no levelling): on a level floor the PV is the marks'.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/profile_metrology.h"

namespace scallop {

struct FeedMarks {
  int64_t samples = 0;
  double peakToValleyMm = 0;  // max - min of the heights
  // The valleys' positions along the profile, mm from its first sample.
  std::vector<double> valleysMm;
  // (last - first) / (valleys - 1), mm; 0 with fewer than two valleys.
  double meanSpacingMm = 0;
};

constexpr double kFeedMarkHysteresis = 0.01;

// Needs at least 3 samples and a positive step (otherwise: no valleys, PV of what is).
FeedMarks measureFeedMarks(const Profile& profile, double hysteresis = kFeedMarkHysteresis);

}  // namespace scallop
