#include "lrsvo/graph/balanced_ranges.h"

namespace lrsvo {

std::vector<int> balancedRanges(const std::vector<double>& work, int parts) {
  double total = 0.0;
  for (double w : work) total += w;
  const int items = static_cast<int>(work.size());
  std::vector<int> bounds{0};
  double done = 0.0;
  for (int i = 0; i + 1 < items && static_cast<int>(bounds.size()) < parts; ++i) {
    done += work[i];
    if (done >= total * static_cast<double>(bounds.size()) / parts) bounds.push_back(i + 1);
  }
  bounds.push_back(items);
  return bounds;
}

}  // namespace lrsvo
