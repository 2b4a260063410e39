#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/sim/flight_truth.h"
#include "lrsvo/sim/ground_texture.h"
#include "lrsvo/sim/image_renderer.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// A synthetic flight rendered frame by frame on demand (nothing on disk, so
// a 9600-frame flight streams): each camera's image from its true pose (the
// base pose and, for camera k >= 1, its deformed extrinsic of that frame).
// next() renders the base camera and defers the others until a frame's
// image(k) asks (the odometry matches across the rig only on the frames it
// keeps); the images do not depend on when or whether they are rendered.
// rig() is the scenario's calibration; the images are undistorted. The
// scenario's faults (FrameFaults) shape the stream: its frames are the
// flight's frames less the dropped ones, numbered 0, 1, ... as delivered;
// a corrupt frame comes without images and with its defect set, a blank one
// with uniform images, and every image carries the exposure gain of its frame.
class SimFrameSource : public FrameSource {
 public:
  // Flies the scenario (throws lrsvo::Error on bad options or a flight that
  // is not above the terrain).
  explicit SimFrameSource(SimScenario scenario);
  // Its renderer refers to its terrain and texture: neither copyable nor movable.
  SimFrameSource(const SimFrameSource&) = delete;
  SimFrameSource& operator=(const SimFrameSource&) = delete;

  std::string name() const override { return "sim:" + scenario_.name; }
  const Rig& rig() const override { return scenario_.rig; }
  const std::vector<LensDistortion>& distortion() const override { return distortion_; }
  int frameCount() const override { return static_cast<int>(delivered_.size()); }
  std::optional<StereoFrame> next() override;
  void skip(int count) override { next_ = std::min(frameCount(), next_ + std::max(count, 0)); }
  // The true base pose (world-from-camera) and secondary extrinsics of every delivered frame.
  GroundTruth groundTruth() const override;

  // Renders every camera of any frame of the flight (0 <= index < the
  // flight's frame count, dropped ones included), with its exposure gain but
  // no other fault, independently of next().
  StereoFrame render(int index) const;
  const SimScenario& scenario() const { return scenario_; }
  const FlightTruth& truth() const { return truth_; }
  // The renderer's time so far, by stage.
  const RenderTimes& renderTimes() const { return renderer_.times(); }

 private:
  StereoFrame renderBase(int index) const;  // images[0] only
  cv::Mat renderCamera(int index, int camera) const;
  int flightFrames() const { return static_cast<int>(truth_.times_s.size()); }

  SimScenario scenario_;
  Terrain terrain_;
  GroundTexture texture_;
  ImageRenderer renderer_;
  FlightTruth truth_;
  std::vector<LensDistortion> distortion_;
  std::vector<int> delivered_;  // the flight's frames the stream delivers, in order
  int next_ = 0;                // into delivered_
};

// The source for `lrsvo run sim:SPEC`: SPEC is "demo", "paper" or a YAML path
// (sim/scenario.h: loadScenario).
std::unique_ptr<FrameSource> makeSimSource(const std::string& spec);

}  // namespace lrsvo
