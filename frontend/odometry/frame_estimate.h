#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// Wall time of the odometry's stages for one frame, in milliseconds.
struct StageTimes {
  double initialize_ms = 0.0;
  double pose_ms = 0.0;
  double triangulate_ms = 0.0;
  double bundle_ms = 0.0;
};

// The odometry's answer for one input frame.
struct FrameEstimate {
  int frame = 0;  // index of the input frame
  double time_s = 0.0;
  bool tracked = false;   // false: no pose (initialising, or tracking lost)
  bool badFrame = false;  // no pose because the images could not be used
  // Not measured: cameraFromWorld is the constant-velocity prediction from the
  // last measured poses (tracking lost a short while before).
  bool predicted = false;
  // Measured against the last segment's map after a loss (its tracks found
  // again): the segment goes on, the frames in between are predicted.
  bool relocalised = false;
  std::string note;  // why a frame has no pose, when known (a bad image, a failed initialisation)
  bool keyframe = false;
  // Tracked stretches between losses are numbered 0, 1, ...; each new one
  // starts where the last one's constant velocity carries it.
  int segment = -1;
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();  // base camera
  std::vector<VertexStereoExtrinsic::Vector6> extrinsics;             // [k - 1]: the window's S when tracked
  // Counts and costs.
  int observations = 0;   // base-camera features of the frame
  int mappedMatches = 0;  // ... of tracks with a point
  int poseInliers = 0;
  int mapPoints = 0;                 // points in the window after this frame
  int windowFrames = 0;              // keyframes in the window
  double windowRmsError_px = 0.0;    // after the window adjustment (keyframes only)
  double outlierThreshold_px = 0.0;  // the window's outlier threshold then (keyframes only)
  int bundleIterations = 0;
  StageTimes times;
};

// "tracked", "predicted", "bad_frame" or "initialising" (no pose: waiting
// for, or given up by, an initialisation), as frames.csv's status column says it.
inline const char* frameStatusName(const FrameEstimate& estimate) {
  if (estimate.tracked) return "tracked";
  if (estimate.predicted) return "predicted";
  return estimate.badFrame ? "bad_frame" : "initialising";
}

}  // namespace lrsvo
