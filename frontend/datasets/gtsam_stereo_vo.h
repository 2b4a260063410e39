#pragma once

#include <map>
#include <string>
#include <vector>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// A real stereo VO back-end problem in the text layout of GTSAM's
// StereoVOExample (KITTI): VO_calibration.txt = fx fy skew u0 v0 baseline;
// VO_camera_poses_<set>.txt = id + 16 numbers of a row-major world-from-camera
// pose; VO_stereo_factors_<set>.txt = pose landmark uL uR v X Y Z (X Y Z: the
// landmark in that camera's frame, used for its start).
//
// Each stereo factor becomes an EdgeProjectBase (uL, v) and an
// EdgeProjectSecondary (uR, v) through a fixed extrinsic c = (baseline, 0, 0).
// The source's model is isotropic 1 px noise on (uL, uR, v): the rectified
// rig predicts the same v in both cameras, so each edge weighs v by 1/2 and
// the cost equals the source's 1/2 (duL^2 + duR^2 + dv^2). The first pose is
// fixed, landmarks start from their first factor, no robust kernel.
struct StereoVoProblem {
  Graph graph;
  PinholeIntrinsics intrinsics;
  double baseline = 0.0;
  VertexStereoExtrinsic* extrinsic = nullptr;  // vertex id 0
  std::vector<VertexPose*> poses;              // file order; vertex ids 1..
  std::map<int, int> landmarkVertexIds;        // file landmark id -> vertex id
  int factorCount = 0;
};

// Throws lrsvo::ParseError (file, line) on malformed or non-finite input,
// unknown pose ids in factors, a non-zero skew or a non-positive baseline.
StereoVoProblem loadGtsamStereoVo(const std::string& directory, const std::string& set = "large");

}  // namespace lrsvo
