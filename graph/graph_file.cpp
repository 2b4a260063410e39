#include "lrsvo/graph/graph_file.h"

#include <fstream>
#include <sstream>
#include <vector>

#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

namespace {

constexpr const char* kHeader = "# lrsvo graph file v1";

template <typename Product>
std::unique_ptr<Product> createType(const std::string& tag, const char* kind) {
  const Registry<Product>& registry = Registry<Product>::instance();
  if (!registry.contains(tag))
    throw Error(std::string("unknown ") + kind + " type '" + tag + "' (registered: " + registry.names() +
                "; lrsvo's own types are added by registerVertexTypes(), registerEdgeTypes() and "
                "registerConstraintTypes())");
  return registry.create(tag);
}

void readVertex(std::istringstream& in, Graph& graph) {
  std::string tag;
  int id = 0, fixed = 0, marginalised = 0;
  if (!(in >> tag >> id >> fixed >> marginalised)) throw Error("VERTEX needs <tag> <id> <fixed> <marginalised>");
  auto vertex = createType<Vertex>(tag, "vertex");
  vertex->setId(id);
  vertex->setFixed(fixed != 0);
  vertex->setMarginalized(marginalised != 0);
  std::vector<double> values(vertex->estimateSize());
  for (double& value : values) value = readNumber(in, tag.c_str());
  vertex->setEstimate(values.data());
  graph.addVertex(std::move(vertex));
}

void readEdge(std::istringstream& in, Graph& graph) {
  std::string tag;
  if (!(in >> tag)) throw Error("EDGE needs a type tag");
  auto edge = createType<Edge>(tag, "edge");
  for (int k = 0; k < edge->vertexCount(); ++k) {
    int id = 0;
    if (!(in >> id)) throw Error(tag + ": missing vertex id " + std::to_string(k));
    Vertex* vertex = graph.vertex(id);
    if (!vertex) throw Error(tag + ": names vertex " + std::to_string(id) + ", which is not in the graph");
    edge->setVertex(k, vertex);
  }
  edge->readData(in);
  graph.addEdge(std::move(edge));
}

}  // namespace

void saveGraph(const Graph& graph, std::ostream& out) {
  out << kHeader << '\n';
  std::vector<double> values;
  for (const auto& v : graph.vertices()) {
    out << "VERTEX " << v->typeTag() << ' ' << v->id() << ' ' << v->fixed() << ' ' << v->marginalized();
    values.resize(v->estimateSize());
    v->getEstimate(values.data());
    for (double x : values) writeNumber(out, x);
    out << '\n';
  }
  for (const auto& e : graph.edges()) {
    out << "EDGE " << e->typeTag();
    for (const Vertex* v : e->vertices()) out << ' ' << v->id();
    e->writeData(out);
    out << '\n';
  }
  out << "END " << graph.vertices().size() << ' ' << graph.edges().size() << '\n';
}

void saveGraphFile(const Graph& graph, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write graph file " + path);
  saveGraph(graph, out);
  if (!out) throw Error("error while writing graph file " + path);
}

Graph loadGraph(std::istream& in, const std::string& sourceName) {
  Graph graph;
  std::string line;
  int lineNumber = 1;
  bool ended = false;
  for (; std::getline(in, line); ++lineNumber) {
    std::istringstream fields(line);
    std::string keyword;
    if (!(fields >> keyword) || keyword[0] == '#') continue;
    try {
      if (ended) throw Error("data after the END line");
      if (keyword == "VERTEX") {
        readVertex(fields, graph);
      } else if (keyword == "EDGE") {
        readEdge(fields, graph);
      } else if (keyword == "END") {
        std::size_t vertices = 0, edges = 0;
        if (!(fields >> vertices >> edges)) throw Error("END needs <vertex count> <edge count>");
        if (vertices != graph.vertices().size() || edges != graph.edges().size())
          throw Error("END counts " + std::to_string(vertices) + " vertices and " + std::to_string(edges) +
                      " edges, the file has " + std::to_string(graph.vertices().size()) + " and " +
                      std::to_string(graph.edges().size()));
        ended = true;
      } else {
        throw Error("unknown line type '" + keyword + "' (expected VERTEX, EDGE or END)");
      }
      std::string extra;
      if (fields >> extra) throw Error("unexpected trailing data '" + extra + "'");
    } catch (const ParseError&) {
      throw;
    } catch (const Error& error) {
      throw ParseError(sourceName, lineNumber, error.what());
    }
  }
  if (!ended) throw ParseError(sourceName, lineNumber, "truncated: the file ends without its END line");
  return graph;
}

Graph loadGraphFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open graph file " + path);
  return loadGraph(in, path);
}

}  // namespace lrsvo
