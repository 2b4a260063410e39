#include "lrsvo/edges/edge_project_secondary_drifting.h"

#include <cmath>

#include "lrsvo/graph/edge_io.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeProjectSecondaryDrifting, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic,
                            VertexExtrinsicRate>;

const VertexStereoExtrinsic& EdgeProjectSecondaryDrifting::extrinsicNow() const {
  // The edges of one keyframe share its dt and come one after another in a
  // solver's loops: the last S(t) built on this thread (its rotations cost
  // six sines and cosines) is reused while s, the rate and dt are unchanged.
  struct Built {
    VertexStereoExtrinsic::Vector6 s, rate;
    double dt_s = 0.0;
    VertexStereoExtrinsic extrinsic;
  };
  thread_local Built last{VertexStereoExtrinsic::Vector6::Constant(NAN), {}, 0.0, VertexStereoExtrinsic()};
  const VertexStereoExtrinsic::Vector6& s = vertexAs<2>()->estimate();
  const VertexStereoExtrinsic::Vector6& rate = vertexAs<3>()->estimate();
  if (last.dt_s != dt_s_ || last.s != s || last.rate != rate) {
    last.s = s;
    last.rate = rate;
    last.dt_s = dt_s_;
    last.extrinsic.setEstimateVector(vertexAs<3>()->extrinsicAfter(s, dt_s_));
  }
  return last.extrinsic;
}

void EdgeProjectSecondaryDrifting::computeResidual(Residual& residual) const {
  residual = projectSecondary(vertexAs<0>()->state(), vertexAs<1>()->estimate(), extrinsicNow().state(), 1.0,
                              camera_.intrinsics) -
             measurement_;
}

void EdgeProjectSecondaryDrifting::computeJacobians() {
  const SecondaryProjectionJacobians j =
      secondaryProjectionJacobians(*vertexAs<0>(), vertexAs<1>()->estimate(), extrinsicNow(), 1.0, camera_.intrinsics);
  jacobian<0>() = j.pose;
  jacobian<1>() = j.point;
  jacobian<2>() = j.extrinsic;
  jacobian<3>() = dt_s_ * j.extrinsic;
}

void EdgeProjectSecondaryDrifting::writeParameters(std::ostream& out) const {
  camera_.write(out);
  writeNumber(out, dt_s_);
}

void EdgeProjectSecondaryDrifting::readParameters(std::istream& in) {
  camera_.read(in, kTypeTag);
  dt_s_ = readNumber(in, kTypeTag);
}

}  // namespace lrsvo
