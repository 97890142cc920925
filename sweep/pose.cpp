#include "sweep/pose.h"

namespace scallop {

size_t ToolPath::cuttingMoves() const {
  size_t n = 0;
  for (const Move& m : moves) n += m.rapid ? 0 : 1;
  return n;
}

}  // namespace scallop
