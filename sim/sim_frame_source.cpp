#include "sim/sim_frame_source.h"

#include <string>
#include <utility>

#include "graph/error.h"

namespace lrsvo {

SimFrameSource::SimFrameSource(SimScenario scenario)
    : scenario_(std::move(scenario)),
      terrain_(scenario_.terrain),
      texture_(scenario_.texture),
      renderer_(terrain_, texture_, scenario_.render, scenario_.seed),
      truth_(simulateFlightTruth(scenario_.flight, terrain_, scenario_.rig, scenario_.deformation)),
      distortion_(scenario_.rig.cameras.size()) {
  scenario_.rig.validate();
}

StereoFrame SimFrameSource::render(int index) const {
  StereoFrame frame = renderBase(index);
  for (int k = 1; k < frame.cameraCount(); ++k) frame.images[k] = renderCamera(index, k);
  return frame;
}

std::optional<StereoFrame> SimFrameSource::next() {
  if (next_ >= frameCount()) return std::nullopt;
  const int index = next_++;
  StereoFrame frame = renderBase(index);
  frame.deferred = std::make_shared<DeferredImages>([this, index](int k) { return renderCamera(index, k); });
  return frame;
}

StereoFrame SimFrameSource::renderBase(int index) const {
  if (index < 0 || index >= frameCount())
    throw Error("sim source: frame " + std::to_string(index) + " outside the flight's " + std::to_string(frameCount()) +
                " frames");
  StereoFrame frame;
  frame.index = index;
  frame.time_s = truth_.times_s[index];
  frame.images.resize(scenario_.rig.cameras.size());
  frame.images[0] = renderCamera(index, 0);
  return frame;
}

cv::Mat SimFrameSource::renderCamera(int index, int camera) const {
  return renderer_.render(scenario_.rig.cameras[camera], trueCameraFromWorld(truth_, index, camera),
                          truth_.times_s[index], index, camera);
}

GroundTruth SimFrameSource::groundTruth() const {
  GroundTruth truth;
  for (std::size_t i = 0; i < truth_.times_s.size(); ++i)
    truth.poses.push_back({truth_.times_s[i], truth_.cameraFromWorld[i].inverse()});
  truth.extrinsics = truth_.extrinsics;
  return truth;
}

std::unique_ptr<FrameSource> makeSimSource(const std::string& spec) {
  return std::make_unique<SimFrameSource>(loadScenario(spec));
}

}  // namespace lrsvo
