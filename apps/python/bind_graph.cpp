// lrsvo.Graph: vertices and edges of the registered types by tag, estimates
// and measurements as numpy arrays, Python residuals, bounds, solves by name,
// and the graph and g2o files.
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/edges/g2o_file.h"
#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/robust_kernel.h"
#include "python_residual_edge.h"

namespace py = pybind11;

namespace lrsvo::python {
namespace {

Vertex& vertexOf(const Graph& graph, int id) {
  Vertex* vertex = graph.vertex(id);
  if (!vertex) throw Error("the graph has no vertex " + std::to_string(id));
  return *vertex;
}

Eigen::VectorXd estimateOf(const Graph& graph, int id) {
  const Vertex& vertex = vertexOf(graph, id);
  Eigen::VectorXd values(vertex.estimateSize());
  vertex.getEstimate(values.data());
  return values;
}

void setEstimateOf(Vertex& vertex, const Eigen::VectorXd& values) {
  if (values.size() != vertex.estimateSize())
    throw Error(std::string(vertex.typeTag()) + " vertex " + std::to_string(vertex.id()) + ": an estimate has " +
                std::to_string(vertex.estimateSize()) + " values, got " + std::to_string(values.size()));
  if (!values.allFinite())
    throw Error(std::string(vertex.typeTag()) + " vertex " + std::to_string(vertex.id()) +
                ": the estimate is not finite");
  vertex.setEstimate(values.data());
}

void addVertex(Graph& graph, const std::string& type, int id, const Eigen::VectorXd& estimate, bool fixed,
               bool marginalized) {
  std::unique_ptr<Vertex> vertex = Registry<Vertex>::instance().create(type);
  vertex->setId(id);
  setEstimateOf(*vertex, estimate);
  vertex->setFixed(fixed);
  vertex->setMarginalized(marginalized);
  graph.addVertex(std::move(vertex));
}

std::vector<Vertex*> verticesOf(const Graph& graph, const std::vector<int>& ids) {
  std::vector<Vertex*> vertices;
  for (int id : ids) vertices.push_back(&vertexOf(graph, id));
  return vertices;
}

std::shared_ptr<RobustKernel> kernelOf(const std::string& kernel, double delta) {
  return kernel.empty() ? nullptr : makeRobustKernel(kernel, delta);
}

// The edge's data as a graph file holds it (graph/graph_file.h): parameters,
// measurement, the information's upper triangle, the kernel; read by the
// type's own readData, so every check of a file applies here too.
std::string edgeData(const Edge& edge, const Eigen::VectorXd& parameters,
                     const std::optional<Eigen::VectorXd>& measurement,
                     const std::optional<Eigen::MatrixXd>& information, const std::string& kernel, double delta) {
  std::ostringstream data;
  writeVector(data, parameters);
  if (measurement) {
    writeVector(data, *measurement);
    const int dimension = edge.residualDimension();
    const Eigen::MatrixXd omega = information ? *information : Eigen::MatrixXd::Identity(dimension, dimension);
    if (omega.rows() != dimension || omega.cols() != dimension)
      throw Error(std::string(edge.typeTag()) + ": the information matrix is " + std::to_string(dimension) + " x " +
                  std::to_string(dimension) + " (the residual's length), got " + std::to_string(omega.rows()) + " x " +
                  std::to_string(omega.cols()));
    if (!omega.isApprox(omega.transpose())) throw Error("the information matrix is not symmetric");
    writeUpperTriangle(data, omega);
    writeKernel(data, kernelOf(kernel, delta).get());
  } else if (information || !kernel.empty()) {
    throw Error("an information matrix or a kernel needs a measurement");
  }
  return data.str();
}

// How many values of parameters and measurement a least-squares edge type
// reads: its default data less the information's upper triangle and the
// kernel's "NONE". Counted, so the sizes are checked before any is misread;
// once per type (add_edge holds the GIL, so the table is never shared).
int leadingValueCount(const Edge& edge) {
  static std::map<std::string, int> countByType;
  const auto [known, inserted] = countByType.try_emplace(edge.typeTag(), 0);
  if (!inserted) return known->second;
  std::ostringstream data;
  edge.writeData(data);
  std::istringstream tokens(data.str());
  int count = 0;
  for (std::string token; tokens >> token;) ++count;
  const int dimension = edge.residualDimension();
  known->second = count - dimension * (dimension + 1) / 2 - 1;
  return known->second;
}

void addEdge(Graph& graph, const std::string& type, const std::vector<int>& ids,
             const std::optional<Eigen::VectorXd>& measurement, const std::optional<Eigen::MatrixXd>& information,
             const Eigen::VectorXd& parameters, const std::string& kernel, double delta) {
  std::unique_ptr<Edge> edge = Registry<Edge>::instance().create(type);
  if (static_cast<int>(ids.size()) != edge->vertexCount())
    throw Error(type + " joins " + std::to_string(edge->vertexCount()) + " vertices, got " +
                std::to_string(ids.size()));
  const std::vector<Vertex*> vertices = verticesOf(graph, ids);
  for (std::size_t k = 0; k < vertices.size(); ++k) edge->setVertex(static_cast<int>(k), vertices[k]);
  if (measurement && edge->residualDimension() > 0) {
    const int expected = leadingValueCount(*edge);
    const Eigen::Index given = parameters.size() + measurement->size();
    if (given != expected)
      throw Error(type + " reads " + std::to_string(expected) + " values of parameters and measurement, got " +
                  std::to_string(parameters.size()) + " + " + std::to_string(measurement->size()));
  }
  std::istringstream data(edgeData(*edge, parameters, measurement, information, kernel, delta));
  edge->readData(data);
  data >> std::ws;
  if (!data.eof())
    throw Error(type +
                ": more values than the type reads (check the sizes of parameters, measurement and "
                "information)");
  graph.addEdge(std::move(edge));
}

void addResidual(Graph& graph, const std::vector<int>& ids, py::function function, int dimension,
                 const std::optional<Eigen::MatrixXd>& information, const std::string& kernel, double delta) {
  const Eigen::MatrixXd omega = information ? *information : Eigen::MatrixXd::Identity(dimension, dimension);
  graph.addEdge(std::make_unique<PythonResidualEdge>(verticesOf(graph, ids), std::move(function), dimension, omega,
                                                     kernelOf(kernel, delta)));
}

using BoundTuple = std::tuple<int, int, double, double>;

SolverSummary optimize(Graph& graph, const std::string& solver, int maxIterations, int threads,
                       double functionTolerance, double gradientTolerance, double parameterTolerance, double maxSeconds,
                       const std::string& damping, bool geodesicAcceleration, bool verbose,
                       const std::vector<BoundTuple>& bounds, const std::string& constraint, bool projectStart) {
  SolverOptions options = SolverOptions::fromName(solver);
  options.maxIterations = maxIterations;
  options.threads = threads;
  options.functionTolerance = functionTolerance;
  options.gradientTolerance = gradientTolerance;
  options.parameterTolerance = parameterTolerance;
  options.maxSeconds = maxSeconds;
  options.lm.damping = dampingFromName(damping);
  options.lm.geodesicAcceleration = geodesicAcceleration;
  options.verbose = verbose;
  if (bounds.empty()) {
    Optimizer optimizer(options);
    py::gil_scoped_release release;
    return optimizer.optimize(graph);
  }
  Bounds box;
  for (const auto& [id, index, lower, upper] : bounds) box.set(&vertexOf(graph, id), index, lower, upper);
  ConstraintSettings settings;
  settings.start = projectStart ? StartPolicy::kProject : StartPolicy::kError;
  py::gil_scoped_release release;
  return optimizeWithBounds(graph, options, box, constraint, settings);
}

template <typename Product>
py::dict namesOf() {
  py::dict names;
  for (const auto& [name, entry] : Registry<Product>::instance().entries()) names[py::str(name)] = entry.description;
  return names;
}

void saveGraphTo(const Graph& graph, const std::string& path, const std::string& format) {
  if (format == "lrsvo")
    saveGraphFile(graph, path);
  else if (format == "g2o")
    saveG2oFile(graph, path);
  else
    throw Error("format must be 'lrsvo' or 'g2o', got '" + format + "'");
}

}  // namespace

void bindGraph(py::module_& m) {
  py::class_<SolverSummary>(m, "SolverSummary", "What one solve did, Ceres style: costs are 1/2 sum rho(|r|^2).")
      .def_readonly("solver", &SolverSummary::solver)
      .def_readonly("initial_cost", &SolverSummary::initialCost)
      .def_readonly("final_cost", &SolverSummary::finalCost)
      .def_readonly("successful_steps", &SolverSummary::successfulSteps)
      .def_readonly("unsuccessful_steps", &SolverSummary::unsuccessfulSteps)
      .def_readonly("total_seconds", &SolverSummary::totalSeconds)
      .def_property_readonly("iterations", &SolverSummary::iterationCount)
      .def_property_readonly("converged", &SolverSummary::converged)
      .def_property_readonly("termination",
                             [](const SolverSummary& s) { return std::string(terminationName(s.termination)); })
      .def_readonly("message", &SolverSummary::message)
      .def_readonly("ordering", &SolverSummary::ordering,
                    "The direct linear solver's fill-reducing ordering ('amd', 'metis', 'nesdis', 'dense'); "
                    "empty for iterative ones.")
      .def_readonly("factorization_flops", &SolverSummary::factorizationFlops,
                    "Flops of one factorisation of the (reduced) system; 0 for iterative solvers.")
      .def("brief_report", &SolverSummary::briefReport, "One line: solver, costs, iterations, why it stopped.")
      .def("full_report", &SolverSummary::fullReport, "The full text report, as `lrsvo bal` prints it.")
      .def("to_json", &SolverSummary::toJson, "The summary as JSON text (what to_dict() parses).")
      .def("__repr__", &SolverSummary::briefReport);

  py::class_<Graph>(m, "Graph",
                    "A factor graph of lrsvo's vertex and edge types (vertex_types(), edge_types()), built "
                    "by type tag, with estimates and measurements as numpy arrays.")
      .def(py::init<>())
      .def("add_vertex", &addVertex, py::arg("type"), py::arg("id"), py::arg("estimate"), py::arg("fixed") = false,
           py::arg("marginalized") = false,
           "Adds a vertex of a registered type (e.g. 'POSE_SE3': tx ty tz qx qy qz qw, 'POINT3': x y z). "
           "Raises lrsvo.Error on an unknown type, a duplicate id or an estimate of the wrong size.")
      .def("add_edge", &addEdge, py::arg("type"), py::arg("vertices"), py::arg("measurement") = std::nullopt,
           py::arg("information") = std::nullopt, py::arg("parameters") = Eigen::VectorXd(), py::arg("kernel") = "",
           py::arg("kernel_delta") = 1.0,
           "Adds an edge of a registered type joining the vertices (ids, in the type's order). parameters are "
           "the type's own numbers before the measurement in a graph file (e.g. fx fy cx cy for 'PROJECT_BASE'); "
           "information defaults to the identity; kernel names a robust kernel ('Huber', 'Cauchy', 'Tukey').")
      .def("add_residual", &addResidual, py::arg("vertices"), py::arg("function"), py::arg("dimension"),
           py::arg("information") = std::nullopt, py::arg("kernel") = "", py::arg("kernel_delta") = 1.0,
           "Adds a residual written in Python: function(x_0, ...) takes the vertices' estimates as numpy arrays "
           "and returns `dimension` numbers. Jacobians are central differences. Slow (every evaluation calls "
           "Python): for prototyping a model. A graph holding one cannot be saved.")
      .def("estimate", &estimateOf, py::arg("id"), "The vertex's estimate as a numpy array (a copy).")
      .def(
          "set_estimate", [](Graph& g, int id, const Eigen::VectorXd& v) { setEstimateOf(vertexOf(g, id), v); },
          py::arg("id"), py::arg("estimate"))
      .def(
          "is_fixed", [](const Graph& g, int id) { return vertexOf(g, id).fixed(); }, py::arg("id"))
      .def(
          "set_fixed", [](Graph& g, int id, bool fixed) { vertexOf(g, id).setFixed(fixed); }, py::arg("id"),
          py::arg("fixed") = true)
      .def(
          "is_marginalized", [](const Graph& g, int id) { return vertexOf(g, id).marginalized(); }, py::arg("id"))
      .def(
          "set_marginalized",
          [](Graph& g, int id, bool marginalized) { vertexOf(g, id).setMarginalized(marginalized); }, py::arg("id"),
          py::arg("marginalized") = true)
      .def(
          "vertex_type", [](const Graph& g, int id) { return std::string(vertexOf(g, id).typeTag()); }, py::arg("id"))
      .def("vertex_ids",
           [](const Graph& g) {
             std::vector<int> ids;
             for (const auto& v : g.vertices()) ids.push_back(v->id());
             return ids;
           })
      .def(
          "remove_vertex",
          [](Graph& g, int id) {
            vertexOf(g, id);
            g.removeVertex(id);
          },
          py::arg("id"), "Removes the vertex and every edge on it.")
      .def("__contains__", [](const Graph& g, int id) { return g.vertex(id) != nullptr; })
      .def_property_readonly("vertex_count", [](const Graph& g) { return g.vertices().size(); })
      .def_property_readonly("edge_count", [](const Graph& g) { return g.edges().size(); })
      .def("cost", &Graph::cost, py::arg("threads") = 1,
           "The objective at the current estimates: 1/2 sum rho(|r|^2) over the edges, evaluated on `threads` "
           "threads (the same value for any count).")
      .def("optimize", &optimize, py::arg("solver") = "lm_schur_cholmod",
           py::arg("max_iterations") = SolverOptions{}.maxIterations, py::arg("threads") = 1,
           py::arg("function_tolerance") = SolverOptions{}.functionTolerance,
           py::arg("gradient_tolerance") = SolverOptions{}.gradientTolerance,
           py::arg("parameter_tolerance") = SolverOptions{}.parameterTolerance,
           py::arg("max_seconds") = SolverOptions{}.maxSeconds, py::arg("damping") = "multiplicative",
           py::arg("geodesic_acceleration") = false, py::arg("verbose") = false,
           py::arg("bounds") = std::vector<BoundTuple>(), py::arg("constraint") = "log_barrier",
           py::arg("project_start") = false,
           "Minimises the cost over the free vertices in place and returns the SolverSummary. solver is "
           "'<algorithm>_<linear solver>' (solvers() lists them). bounds: (vertex id, parameter index, lower, "
           "upper) on Euclidean vertices, kept by the constraint method named (constraint_methods(), with "
           "settings as 'log_barrier:mu=0.01'); a start outside them raises unless project_start. "
           "geodesic_acceleration corrects each Levenberg-Marquardt step by the residuals' curvature along it "
           "(one more residual evaluation and solve per step; for hard small problems). The GIL is released "
           "while it runs.")
      .def("save", &saveGraphTo, py::arg("path"), py::arg("format") = "lrsvo",
           "Writes lrsvo's graph file ('lrsvo', exact round trip) or a g2o file ('g2o': SE2/SE3 pose graphs).");

  m.def("load_graph", &loadGraphFile, py::arg("path"), "Reads lrsvo's graph file (lrsvo.ParseError names the line).");
  m.def("load_g2o", &loadG2oFile, py::arg("path"), "Reads a g2o pose graph (VERTEX_SE2/SE3:QUAT, EDGE_SE2/SE3:QUAT).");
  m.def("vertex_types", &namesOf<Vertex>, "The vertex type tags add_vertex takes, with their C++ classes.");
  m.def("edge_types", &namesOf<Edge>, "The edge type tags add_edge takes, with their C++ classes.");
  m.def("robust_kernels", &namesOf<RobustKernel>, "The robust kernels by name.");
  m.def(
      "solvers",
      [] {
        std::vector<std::string> names;
        for (const auto& [algorithm, a] : Registry<OptimizationAlgorithm>::instance().entries())
          for (const auto& [linear, l] : Registry<LinearSolver>::instance().entries())
            names.push_back(algorithm + "_" + linear);
        return names;
      },
      "Every solver name optimize() takes: '<algorithm>_<linear solver>'.");
  m.def("constraint_methods", &namesOf<ConstraintMethod>, "The constraint methods optimize() takes by name.");
}

}  // namespace lrsvo::python
