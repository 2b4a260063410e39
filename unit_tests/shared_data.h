#pragma once

#include <string>

namespace lrsvo::test {

// Real EuRoC frames from ../shared/data (its README): the first seconds of
// V1_01, a nearly still vehicle.
inline const std::string kEuroc = LRSVO_SHARED_DATA "/euroc_v101_micro";

}  // namespace lrsvo::test
