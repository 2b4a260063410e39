#include "lrsvo/frontend/datasets/frame_source.h"

#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

const cv::Mat& DeferredImages::image(int camera) {
  auto found = made_.find(camera);
  if (found == made_.end()) found = made_.emplace(camera, produce_(camera)).first;
  return found->second;
}

const cv::Mat& StereoFrame::image(int camera) const {
  if (camera < 0 || camera >= cameraCount())
    throw Error("frame " + std::to_string(index) + ": no camera " + std::to_string(camera) + " among " +
                std::to_string(cameraCount()));
  const cv::Mat& held = images[static_cast<std::size_t>(camera)];
  return held.empty() && deferred ? deferred->image(camera) : held;
}

}  // namespace lrsvo
