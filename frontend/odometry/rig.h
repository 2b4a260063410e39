#pragma once

#include <string>
#include <vector>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/edges/pinhole.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// One camera of a rig: pinhole intrinsics (images undistorted) and image size.
struct Camera {
  PinholeIntrinsics intrinsics;
  int width = 0;
  int height = 0;

  bool inImage(const Eigen::Vector2d& pixel, double margin_px = 0.0) const {
    return pixel.x() >= margin_px && pixel.y() >= margin_px && pixel.x() < width - margin_px &&
           pixel.y() < height - margin_px;
  }
};

// Focal length in pixels from the optics: lens focal length over pixel pitch.
double focalLengthPixels(double lens_mm, double sensorWidth_mm, int imageWidth);
// Focal length in pixels from the horizontal field of view.
double focalLengthFromFov(double horizontalFov_rad, int imageWidth);

// A rig of cameras: camera 0 is the base, camera k >= 1 sits at its calibrated
// extrinsic s_k = (c, roll, pitch, yaw) relative to the base (docs/method.md), with
// one tolerance q, shared by every secondary camera, on each of the six
// numbers (the box p +- q of eq. 17-19).
struct Rig {
  std::vector<Camera> cameras;                             // [0] = base
  std::vector<VertexStereoExtrinsic::Vector6> extrinsics;  // [k - 1] for camera k >= 1
  VertexStereoExtrinsic::Vector6 tolerance =
      (VertexStereoExtrinsic::Vector6() << 1e-3, 1e-3, 1e-3, 0.01, 0.01, 0.01).finished();

  int secondaryCount() const { return static_cast<int>(cameras.size()) - 1; }
  // Camera k's pose (camera-from-world) for a base pose and the rig's
  // calibration, or the given extrinsic (a deformed rig).
  Eigen::Isometry3d cameraFromWorld(const Eigen::Isometry3d& baseFromWorld, int camera) const;
  // The box around calibration for secondary camera k on `vertex`.
  void addBounds(Bounds& bounds, Vertex* vertex, int camera) const;
  // The nearest extrinsic to s inside camera k's box.
  VertexStereoExtrinsic::Vector6 clampToBox(const VertexStereoExtrinsic::Vector6& s, int camera) const;
  // Throws lrsvo::Error when the rig is unusable (no camera, bad sizes, missing extrinsics).
  void validate() const;
};

// The paper's rig: two cameras, 0.7 m baseline along the base camera's x
// axis (the fuselage), 1280x960 with a 42 deg horizontal field of view.
Rig paperRig(double baseline_m = 0.7, int width = 1280, int height = 960, double horizontalFov_rad = 0.733);

}  // namespace lrsvo
