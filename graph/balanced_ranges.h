#pragma once

#include <vector>

namespace lrsvo {

// Splits items [0, work.size()) into at most `parts` contiguous ranges of
// about equal total work; returns the ranges' bounds, first 0, last the item
// count (so one range more than there are inner bounds). The split depends on
// the work alone.
std::vector<int> balancedRanges(const std::vector<double>& work, int parts);

}  // namespace lrsvo
