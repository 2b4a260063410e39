#include "lrsvo/edges/pinhole.h"

#include <string>

#include "lrsvo/graph/edge_io.h"

namespace lrsvo {

void PinholeIntrinsics::write(std::ostream& out) const {
  writeNumber(out, fx);
  writeNumber(out, fy);
  writeNumber(out, cx);
  writeNumber(out, cy);
}

void PinholeIntrinsics::read(std::istream& in, const char* what) {
  fx = readNumber(in, what);
  fy = readNumber(in, what);
  cx = readNumber(in, what);
  cy = readNumber(in, what);
  if (fx <= 0.0 || fy <= 0.0) throw Error(std::string(what) + ": focal lengths must be positive");
}

}  // namespace lrsvo
