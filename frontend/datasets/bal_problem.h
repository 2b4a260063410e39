#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/graph/graph.h"

namespace lrsvo {

// A bundle-adjustment problem in the BAL format (Agarwal et al., "Bundle
// Adjustment in the Large"): cameras are 9 numbers (angle-axis, translation,
// f, k1, k2), points 3, observations (camera, point, x, y) in pixels with
// the origin at the image centre.
struct BalObservation {
  int camera = 0;
  int point = 0;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

struct BalProblem {
  std::vector<Eigen::Matrix<double, 9, 1>> cameras;
  std::vector<Eigen::Vector3d> points;
  std::vector<BalObservation> observations;
};

// Throws lrsvo::ParseError (file, line) on malformed, truncated or
// non-finite input and on observations naming missing cameras or points.
BalProblem readBal(const std::string& path);
// Writes with 17 significant digits: readBal(writeBal(p)) == p exactly.
void writeBal(const BalProblem& problem, const std::string& path);

// Vertex ids: cameras 0..C-1 (VertexBalCamera), points C..C+P-1
// (VertexPoint3, marginalised); one EdgeBalProjection per observation,
// with an optional robust kernel ("" for none). `makeEdge`, when given, makes
// the edges: an EdgeBalProjection subclass (other Jacobians, say).
Graph makeBalGraph(const BalProblem& problem, const std::string& kernel = "", double kernelDelta = 1.0,
                   const std::function<std::unique_ptr<EdgeBalProjection>()>& makeEdge = nullptr);
// Copies the graph's estimates back into the problem (same layout as makeBalGraph).
void updateFromGraph(BalProblem& problem, const Graph& graph);

// Seeded synthetic problem of realistic shape: cameras on a ring/grid looking
// at a point cloud, each point seen by several cameras, pixel noise, then the
// start perturbed (rotation, translation, point position) like the BAL sets.
struct BalGeneratorOptions {
  int cameras = 50;
  int points = 10000;
  int observationsPerPoint = 6;  // mean; each point is seen by at least 2 cameras, at most all
  double pixelNoise = 1.0;       // sigma of the observations, pixels
  double rotationNoise = 1e-3;   // sigma of the start's angle-axis perturbation, rad
  double translationNoise = 0.02;
  double pointNoise = 0.05;
  std::uint64_t seed = 1;
};
BalProblem generateBalProblem(const BalGeneratorOptions& options);

// The BAL camera model (as EdgeBalProjection): predicted pixel of a world point.
Eigen::Vector2d projectBal(const Eigen::Matrix<double, 9, 1>& camera, const Eigen::Vector3d& point);
// Root mean square of the reprojection residuals per image coordinate, in
// pixels (about the pixel noise sigma at a good solution); 0 without observations.
double rmsReprojectionError(const BalProblem& problem);

}  // namespace lrsvo
