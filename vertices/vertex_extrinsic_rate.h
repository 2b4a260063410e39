#pragma once

#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// The extrinsic `dt_s` seconds after the time it was s, changing at `rate` per second.
inline VertexStereoExtrinsic::Vector6 extrinsicAfter(const VertexStereoExtrinsic::Vector6& s,
                                                     const VertexStereoExtrinsic::Vector6& rate, double dt_s) {
  return s + dt_s * rate;
}

// How fast a secondary camera's extrinsic s = (x, y, z, roll, pitch, yaw)
// changes, per second (m/s, rad/s): the window's S at time t is
// s + (t - t_ref) * rate. A flexing rig moves S by a few mrad within the one
// or two seconds a window spans; one constant S per window lags that motion,
// and the newest keyframes, whose stereo rays the lag bends most, step too far.
class VertexExtrinsicRate : public VectorVertex<6> {
 public:
  static constexpr const char* kTypeTag = "STEREO_EXTRINSIC_RATE";
  using Vector6 = VertexStereoExtrinsic::Vector6;
  explicit VertexExtrinsicRate(int id = -1, const Vector6& rate = Vector6::Zero());

  // The extrinsic `dt_s` seconds after s's reference time.
  Vector6 extrinsicAfter(const Vector6& s, double dt_s) const { return lrsvo::extrinsicAfter(s, estimate_, dt_s); }
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexExtrinsicRate>(*this); }
};

}  // namespace lrsvo
