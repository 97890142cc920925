#include "sweep/pose.h"

namespace scallop {

size_t ToolPath::cuttingMoves() const {
  size_t n = 0;
  for (const Move& m : moves) n += m.rapid ? 0 : 1;
  return n;
}

ToolPath ToolPath::single(size_t k) const {
  ToolPath one;
  one.moves.push_back(moves.at(k));
  Move& m = one.moves.back();
  if (m.tool < cutters.size()) {
    one.cutters.push_back(cutters[m.tool]);
    m.tool = 0;
  }
  if (m.rotary > 0 && m.rotary <= rotary.size()) {
    one.rotary.push_back(rotary[m.rotary - 1]);
    m.rotary = 1;
  }
  one.machine = machine;
  return one;
}

}  // namespace scallop
