#include "lrsvo/edges/g2o_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

namespace {

constexpr const char* kVertexSE2 = "VERTEX_SE2";
constexpr const char* kEdgeSE2 = "EDGE_SE2";
constexpr const char* kVertexSE3 = "VERTEX_SE3:QUAT";
constexpr const char* kEdgeSE3 = "EDGE_SE3:QUAT";
constexpr const char* kFix = "FIX";

// The fields of one line after its tag, read strictly: counts, integers and
// finite numbers are checked, and errors name the tag.
class Fields {
 public:
  Fields(std::string tag, std::vector<std::string> fields) : tag_(std::move(tag)), fields_(std::move(fields)) {}

  std::size_t size() const { return fields_.size(); }
  const std::string& tag() const { return tag_; }

  void expectCount(std::size_t count) const {
    if (fields_.size() < count)
      throw Error(tag_ + ": truncated line, " + std::to_string(count) + " values expected after the tag, found " +
                  std::to_string(fields_.size()));
    if (fields_.size() > count)
      throw Error(tag_ + ": unexpected trailing data '" + fields_[count] + "' after " + std::to_string(count) +
                  " values");
  }

  int id(std::size_t k) const {
    const std::string& text = fields_[k];
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      throw Error(tag_ + ": '" + text + "' is not a vertex id");
    return value;
  }

  double number(std::size_t k) const {
    const std::string& text = fields_[k];
    // from_chars reads what strtod reads except a leading '+', which some writers emit.
    const char* begin = text.data() + (text.size() > 1 && text[0] == '+' && text[1] != '-' ? 1 : 0);
    const char* last = text.data() + text.size();
    double value = 0.0;
    const auto [end, error] = std::from_chars(begin, last, value);
    if (error == std::errc::result_out_of_range) throw Error(tag_ + ": '" + text + "' is out of the range of a double");
    if (error != std::errc() || end != last) throw Error(tag_ + ": '" + text + "' is not a number");
    if (!std::isfinite(value)) throw Error(tag_ + ": value '" + text + "' is not finite");
    return value;
  }

  template <int N>
  Eigen::Matrix<double, N, 1> vector(std::size_t first) const {
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = number(first + i);
    return v;
  }

  // The symmetric matrix of a row-major upper triangle.
  template <int N>
  Eigen::Matrix<double, N, N> upperTriangle(std::size_t first) const {
    Eigen::Matrix<double, N, N> m;
    for (int r = 0; r < N; ++r)
      for (int c = r; c < N; ++c) m(r, c) = m(c, r) = number(first++);
    return m;
  }

 private:
  std::string tag_;
  std::vector<std::string> fields_;
};

// x y z qx qy qz qw from `first` on.
Eigen::Quaterniond quaternionAt(const Fields& fields, std::size_t first) {
  return Eigen::Quaterniond(fields.number(first + 3), fields.number(first), fields.number(first + 1),
                            fields.number(first + 2));
}

template <typename VertexType>
VertexType& vertexOf(const Graph& graph, const Fields& fields, std::size_t k) {
  const int id = fields.id(k);
  Vertex* vertex = graph.vertex(id);
  if (!vertex) throw Error(fields.tag() + ": names vertex " + std::to_string(id) + ", which is not in the graph");
  auto* typed = dynamic_cast<VertexType*>(vertex);
  if (!typed)
    throw Error(fields.tag() + ": vertex " + std::to_string(id) + " is a " + vertex->typeTag() + ", not a " +
                VertexType::kTypeTag);
  return *typed;
}

void readVertexSE2(const Fields& fields, Graph& graph) {
  fields.expectCount(4);
  graph.addVertex(std::make_unique<VertexSE2>(fields.id(0), fields.vector<3>(1)));
}

void readVertexSE3(const Fields& fields, Graph& graph) {
  fields.expectCount(8);
  auto vertex = std::make_unique<VertexSE3Quat>(fields.id(0));
  vertex->setPose(fields.vector<3>(1), quaternionAt(fields, 4));
  graph.addVertex(std::move(vertex));
}

void readEdgeSE2(const Fields& fields, Graph& graph) {
  fields.expectCount(11);
  auto edge = std::make_unique<EdgeSE2>();
  edge->setVertex(0, &vertexOf<VertexSE2>(graph, fields, 0));
  edge->setVertex(1, &vertexOf<VertexSE2>(graph, fields, 1));
  edge->setMeasurement(fields.vector<3>(2));
  edge->setInformation(fields.upperTriangle<3>(5));
  graph.addEdge(std::move(edge));
}

void readEdgeSE3(const Fields& fields, Graph& graph) {
  fields.expectCount(30);
  auto edge = std::make_unique<EdgeSE3Quat>();
  edge->setVertex(0, &vertexOf<VertexSE3Quat>(graph, fields, 0));
  edge->setVertex(1, &vertexOf<VertexSE3Quat>(graph, fields, 1));
  edge->setRelativePose(fields.vector<3>(2), quaternionAt(fields, 5));
  edge->setInformation(fields.upperTriangle<6>(9));
  graph.addEdge(std::move(edge));
}

void readFix(const Fields& fields, const Graph& graph) {
  if (fields.size() == 0) throw Error("FIX: truncated line, at least one vertex id expected");
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const int id = fields.id(k);
    Vertex* vertex = graph.vertex(id);
    if (!vertex) throw Error("FIX: names vertex " + std::to_string(id) + ", which is not in the graph");
    vertex->setFixed(true);
  }
}

void readLine(const std::string& tag, const Fields& fields, Graph& graph) {
  if (tag == kVertexSE2) return readVertexSE2(fields, graph);
  if (tag == kVertexSE3) return readVertexSE3(fields, graph);
  if (tag == kEdgeSE2) return readEdgeSE2(fields, graph);
  if (tag == kEdgeSE3) return readEdgeSE3(fields, graph);
  if (tag == kFix) return readFix(fields, graph);
  throw Error("unknown tag '" + tag + "' (supported: VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT, EDGE_SE3:QUAT, FIX)");
}

void writeVertex(std::ostream& out, const Vertex& vertex) {
  if (const auto* planar = dynamic_cast<const VertexSE2*>(&vertex)) {
    out << kVertexSE2 << ' ' << vertex.id();
    writeVector(out, planar->pose());
  } else if (const auto* spatial = dynamic_cast<const VertexSE3Quat*>(&vertex)) {
    out << kVertexSE3 << ' ' << vertex.id();
    writeVector(out, spatial->translation());
    writeVector(out, spatial->quaternion().coeffs());  // x y z w
  } else {
    throw Error(std::string("saveG2o: vertex ") + std::to_string(vertex.id()) + " is a " + vertex.typeTag() +
                ", which has no g2o form");
  }
  out << '\n';
  if (vertex.fixed()) out << kFix << ' ' << vertex.id() << '\n';
}

void writeEdge(std::ostream& out, const Edge& edge) {
  const auto writeIds = [&](const char* tag) {
    out << tag << ' ' << edge.vertex(0)->id() << ' ' << edge.vertex(1)->id();
  };
  if (const auto* planar = dynamic_cast<const EdgeSE2*>(&edge)) {
    if (planar->robustKernel()) throw Error("saveG2o: an EDGE_SE2 has a robust kernel, which g2o files cannot hold");
    writeIds(kEdgeSE2);
    writeVector(out, planar->measurement());
    writeUpperTriangle(out, planar->information());
  } else if (const auto* spatial = dynamic_cast<const EdgeSE3Quat*>(&edge)) {
    if (spatial->robustKernel())
      throw Error("saveG2o: an EDGE_SE3:QUAT has a robust kernel, which g2o files cannot hold");
    writeIds(kEdgeSE3);
    writeVector(out, spatial->relativeTranslation());
    writeVector(out, spatial->relativeQuaternion().coeffs());
    writeUpperTriangle(out, spatial->information());
  } else {
    throw Error(std::string("saveG2o: an edge of type ") + edge.typeTag() + " has no g2o form");
  }
  out << '\n';
}

}  // namespace

Graph loadG2o(std::istream& in, const std::string& sourceName) {
  Graph graph;
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    std::istringstream words(line);
    std::string tag, word;
    if (!(words >> tag) || tag[0] == '#') continue;
    std::vector<std::string> fields;
    while (words >> word) fields.push_back(word);
    try {
      readLine(tag, Fields(tag, std::move(fields)), graph);
    } catch (const Error& error) {
      throw ParseError(sourceName, lineNumber, error.what());
    }
  }
  if (in.bad()) throw Error("error while reading " + sourceName);
  return graph;
}

Graph loadG2oFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open g2o file " + path);
  return loadG2o(in, path);
}

void saveG2o(const Graph& graph, std::ostream& out) {
  // Formatted whole before any of it is written, so a refused type leaves `out` untouched.
  std::ostringstream text;
  for (const auto& vertex : graph.vertices()) writeVertex(text, *vertex);
  for (const auto& edge : graph.edges()) writeEdge(text, *edge);
  out << text.str();
}

void saveG2oFile(const Graph& graph, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write g2o file " + path);
  saveG2o(graph, out);
  if (!out) throw Error("error while writing g2o file " + path);
}

}  // namespace lrsvo
