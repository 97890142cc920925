// CuttingModel: what surface a cutter leaves (job key `cutting`, docs/teeth.md).
//   * Envelope: the lowest point of the swept solid of revolution, the limit of an
//     infinitely fine feed (swept_move.h).
//   * Teeth: the lowest point that any cutting edge passes through (tooth_sweep.h). The
//     spindle angle is phi(s) = phi0 + 2 pi s / (flutes fz), s the tip's distance along
//     the whole path (rapids included, in file order), so the marks are continuous from
//     move to move. The spindle turns clockwise seen from the shank (M3) unless the job
//     or the move says counter-clockwise (M4): the mirror image (tooth_sweep.h).
#pragma once

#include <cstdint>

namespace scallop {

enum class CuttingModelKind : uint8_t { Envelope, Teeth };

struct CuttingModel {
  CuttingModelKind kind = CuttingModelKind::Envelope;
  // fz, mm per tooth: the feed of a move whose Move::feedPerTooth is 0 (a G-code move
  // carries F / (S flutes) of its own).
  double feedPerTooth = 0;
  double phaseDeg = 0;  // phi0, degrees
  // Job key "spindle": the direction of a move that sets none (Move::spindle).
  bool counterClockwise = false;
  bool teeth() const { return kind == CuttingModelKind::Teeth; }
};

}  // namespace scallop
