#include "lrsvo/sim/sim_frame_source.h"

#include <string>
#include <utility>

#include "lrsvo/graph/error.h"

namespace lrsvo {

SimFrameSource::SimFrameSource(SimScenario scenario)
    : scenario_(std::move(scenario)),
      terrain_(scenario_.terrain),
      texture_(scenario_.texture),
      renderer_(terrain_, texture_, scenario_.render, scenario_.seed),
      truth_(simulateFlightTruth(scenario_.flight, terrain_, scenario_.rig, scenario_.deformation)),
      distortion_(scenario_.rig.cameras.size()) {
  scenario_.rig.validate();
  scenario_.faults.validate();
  for (int i = 0; i < flightFrames(); ++i)
    if (!scenario_.faults.dropped(i)) delivered_.push_back(i);
}

StereoFrame SimFrameSource::render(int index) const {
  StereoFrame frame = renderBase(index);
  for (int k = 1; k < frame.cameraCount(); ++k) frame.images[k] = renderCamera(index, k);
  return frame;
}

std::optional<StereoFrame> SimFrameSource::next() {
  if (next_ >= frameCount()) return std::nullopt;
  const int position = next_++;
  const int index = delivered_[static_cast<std::size_t>(position)];
  const FrameFaults& faults = scenario_.faults;
  StereoFrame frame;
  if (faults.corrupt(index) || faults.blank(index)) {
    frame.time_s = truth_.times_s[index];
    frame.images.resize(scenario_.rig.cameras.size());
    if (faults.corrupt(index)) frame.defect = "corrupt image (a simulated fault)";
    for (std::size_t k = 0; k < frame.images.size() && faults.blank(index); ++k)
      frame.images[k] =
          cv::Mat(scenario_.rig.cameras[k].height, scenario_.rig.cameras[k].width, CV_8UC1, cv::Scalar(128));
  } else {
    frame = renderBase(index);
    frame.deferred = std::make_shared<DeferredImages>([this, index](int k) { return renderCamera(index, k); });
  }
  frame.index = position;
  return frame;
}

StereoFrame SimFrameSource::renderBase(int index) const {
  if (index < 0 || index >= flightFrames())
    throw Error("sim source: frame " + std::to_string(index) + " outside the flight's " +
                std::to_string(flightFrames()) + " frames");
  StereoFrame frame;
  frame.index = index;
  frame.time_s = truth_.times_s[index];
  frame.images.resize(scenario_.rig.cameras.size());
  frame.images[0] = renderCamera(index, 0);
  return frame;
}

cv::Mat SimFrameSource::renderCamera(int index, int camera) const {
  cv::Mat image = renderer_.render(scenario_.rig.cameras[camera], trueCameraFromWorld(truth_, index, camera),
                                   truth_.times_s[index], index, camera);
  const double gain = scenario_.faults.gainAt(index);
  if (gain != 1.0) image.convertTo(image, CV_8U, gain);  // saturates at 255, as a sensor does
  return image;
}

GroundTruth SimFrameSource::groundTruth() const {
  GroundTruth truth;
  for (int i : delivered_) {
    truth.poses.push_back({truth_.times_s[i], truth_.cameraFromWorld[i].inverse()});
    truth.extrinsics.push_back(truth_.extrinsics[i]);
  }
  return truth;
}

std::unique_ptr<FrameSource> makeSimSource(const std::string& spec) {
  return std::make_unique<SimFrameSource>(loadScenario(spec));
}

}  // namespace lrsvo
