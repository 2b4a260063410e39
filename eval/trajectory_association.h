#pragma once

#include "lrsvo/frontend/datasets/pose_file.h"

namespace lrsvo {

// An estimate and the truth cut down to the poses that match: pose i of one
// belongs to pose i of the other.
struct AssociatedTrajectories {
  Trajectory estimate;
  Trajectory truth;
};

// Matches by time as the TUM benchmark's associate.py: every pair of stamps at
// most `maxDifference_s` apart is a candidate; candidates are taken closest
// first, each pose in at most one pair. The result is in the estimate's time order.
AssociatedTrajectories associateByTime(const Trajectory& estimate, const Trajectory& truth,
                                       double maxDifference_s = 0.02);

// Matches pose i with pose i (KITTI files); throws lrsvo::Error unless both have the same length.
AssociatedTrajectories associateByIndex(const Trajectory& estimate, const Trajectory& truth);

}  // namespace lrsvo
