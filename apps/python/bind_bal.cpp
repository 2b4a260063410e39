// lrsvo.BalProblem: BAL files, the seeded generator, and their graphs.
#include <string>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/error.h"

namespace py = pybind11;

namespace lrsvo::python {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

RowMajor camerasOf(const BalProblem& p) {
  RowMajor cameras(p.cameras.size(), 9);
  for (std::size_t i = 0; i < p.cameras.size(); ++i) cameras.row(i) = p.cameras[i].transpose();
  return cameras;
}

RowMajor pointsOf(const BalProblem& p) {
  RowMajor points(p.points.size(), 3);
  for (std::size_t i = 0; i < p.points.size(); ++i) points.row(i) = p.points[i].transpose();
  return points;
}

RowMajor observationsOf(const BalProblem& p) {
  RowMajor observations(p.observations.size(), 4);
  for (std::size_t i = 0; i < p.observations.size(); ++i) {
    const BalObservation& o = p.observations[i];
    observations.row(i) << o.camera, o.point, o.pixel.x(), o.pixel.y();
  }
  return observations;
}

template <int Columns>
void setRows(std::vector<Eigen::Matrix<double, Columns, 1>>& rows, const Eigen::Ref<const RowMajor>& values,
             const char* what) {
  if (values.cols() != Columns || values.rows() != static_cast<Eigen::Index>(rows.size()))
    throw Error(std::string(what) + " must be a " + std::to_string(rows.size()) + " x " + std::to_string(Columns) +
                " array, got " + std::to_string(values.rows()) + " x " + std::to_string(values.cols()));
  if (!values.allFinite()) throw Error(std::string(what) + " must be finite");
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = values.row(i).transpose();
}

}  // namespace

void bindBal(py::module_& m) {
  py::class_<BalProblem>(m, "BalProblem",
                         "A bundle-adjustment problem in the BAL format: cameras (C x 9: angle-axis, translation, "
                         "f, k1, k2), points (P x 3), observations (N x 4: camera, point, x, y in pixels from the "
                         "image centre).")
      .def_static("read", &readBal, py::arg("path"), "Reads a BAL text file (lrsvo.ParseError names the line).")
      .def_static(
          "generate",
          [](int cameras, int points, int observationsPerPoint, double pixelNoise, std::uint64_t seed) {
            BalGeneratorOptions options;
            options.cameras = cameras;
            options.points = points;
            options.observationsPerPoint = observationsPerPoint;
            options.pixelNoise = pixelNoise;
            options.seed = seed;
            return generateBalProblem(options);
          },
          py::arg("cameras") = BalGeneratorOptions{}.cameras, py::arg("points") = BalGeneratorOptions{}.points,
          py::arg("observations_per_point") = BalGeneratorOptions{}.observationsPerPoint,
          py::arg("pixel_noise") = BalGeneratorOptions{}.pixelNoise, py::arg("seed") = BalGeneratorOptions{}.seed,
          "The seeded synthetic problem of `lrsvo bal --generate` (same options, same problem).")
      .def("write", &writeBal, py::arg("path"), "Writes the BAL text file (17 digits: read(write(p)) is exact).")
      .def_property("cameras", &camerasOf,
                    [](BalProblem& p, const Eigen::Ref<const RowMajor>& v) { setRows<9>(p.cameras, v, "cameras"); })
      .def_property("points", &pointsOf,
                    [](BalProblem& p, const Eigen::Ref<const RowMajor>& v) { setRows<3>(p.points, v, "points"); })
      .def_property_readonly("observations", &observationsOf)
      .def(
          "graph",
          [](const BalProblem& p, const std::string& kernel, double delta) { return makeBalGraph(p, kernel, delta); },
          py::arg("kernel") = "", py::arg("kernel_delta") = 1.0,
          "The problem as a Graph: cameras are vertices 0..C-1 ('BAL_CAMERA'), points C..C+P-1 ('POINT3', "
          "marginalised), one 'BAL_PROJECTION' edge per observation.")
      .def("update_from", &updateFromGraph, py::arg("graph"), "Copies a solved graph's estimates back.")
      .def("rms_reprojection_error", &rmsReprojectionError,
           "RMS of the reprojection residuals per image coordinate, pixels.");
}

}  // namespace lrsvo::python
