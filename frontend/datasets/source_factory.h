#pragma once

#include <memory>
#include <string>

#include "lrsvo/frontend/datasets/frame_source.h"

namespace lrsvo {

// Opens a data set on disk as a FrameSource. "euroc:DIR" and "kitti:DIR" force
// the layout; a bare DIR is recognised by what it holds: DIR/mav0 -> EuRoC,
// DIR/calib.txt and DIR/image_0 -> KITTI. Throws lrsvo::Error otherwise.
// (Rendered "sim:" sources live in sim/.)
std::unique_ptr<FrameSource> openDatasetSource(const std::string& spec);

}  // namespace lrsvo
