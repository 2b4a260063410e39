#pragma once

#include "lrsvo/eval/study.h"

namespace lrsvo {

// The paper's studies, one per file of eval/studies/; Study::addBuiltins registers them.
Study depthDistributionStudy();
Study disparityStudy();
Study epipolarStudy();
Study initAltitudeStudy();
Study initScaleStudy();
Study rangeBiasStudy();
Study triangulationStudy();

}  // namespace lrsvo
