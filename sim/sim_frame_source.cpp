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
  if (index < 0 || index >= frameCount())
    throw Error("sim source: frame " + std::to_string(index) + " outside the flight's " + std::to_string(frameCount()) +
                " frames");
  StereoFrame frame;
  frame.index = index;
  frame.time_s = truth_.times_s[index];
  for (int k = 0; k < static_cast<int>(scenario_.rig.cameras.size()); ++k)
    frame.images.push_back(
        renderer_.render(scenario_.rig.cameras[k], trueCameraFromWorld(truth_, index, k), frame.time_s, index, k));
  return frame;
}

std::optional<StereoFrame> SimFrameSource::next() {
  if (next_ >= frameCount()) return std::nullopt;
  return render(next_++);
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
