#include "lrsvo/graph/graph.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lrsvo/graph/edge_costs.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

void Graph::insertVertex(std::unique_ptr<Vertex> vertex) {
  if (!vertex) throw Error("addVertex: null vertex");
  const int id = vertex->id();
  if (!byId_.emplace(id, vertex.get()).second) throw Error("addVertex: duplicate vertex id " + std::to_string(id));
  vertices_.push_back(std::move(vertex));
}

void Graph::insertEdge(std::unique_ptr<Edge> edge) {
  if (!edge) throw Error("addEdge: null edge");
  for (int k = 0; k < edge->vertexCount(); ++k) {
    const Vertex* v = edge->vertex(k);
    // The message is built only on failure: graphs of millions of edges pass through here.
    const auto where = [&] { return std::string("addEdge ") + edge->typeTag() + ": vertex slot " + std::to_string(k); };
    if (!v) throw Error(where() + " is empty");
    if (vertex(v->id()) != v) throw Error(where() + " names vertex " + std::to_string(v->id()) + ", not in the graph");
    if (!edge->acceptsVertex(k, *v))
      throw Error(where() + " cannot hold vertex " + std::to_string(v->id()) + " of type " + v->typeTag());
  }
  edges_.push_back(std::move(edge));
}

void Graph::removeVertex(int id) {
  Vertex* target = vertex(id);
  if (!target) throw Error("removeVertex: no vertex " + std::to_string(id));
  std::erase_if(edges_, [&](const std::unique_ptr<Edge>& e) {
    return std::find(e->vertices().begin(), e->vertices().end(), target) != e->vertices().end();
  });
  byId_.erase(id);
  std::erase_if(vertices_, [&](const std::unique_ptr<Vertex>& v) { return v.get() == target; });
}

void Graph::removeEdge(const Edge* edge) {
  std::erase_if(edges_, [&](const std::unique_ptr<Edge>& e) { return e.get() == edge; });
}

Vertex* Graph::vertex(int id) const {
  auto it = byId_.find(id);
  return it == byId_.end() ? nullptr : it->second;
}

double Graph::cost(int threads) const {
  if (threads < 1) throw Error("cost: threads must be at least 1, got " + std::to_string(threads));
  return sumOfEdgeCosts(edges_, threads);
}

std::vector<double> Graph::estimates() const {
  std::vector<double> values;
  for (const auto& vertex : vertices_) {
    const std::size_t start = values.size();
    values.resize(start + static_cast<std::size_t>(vertex->estimateSize()));
    vertex->getEstimate(values.data() + start);
  }
  return values;
}

void Graph::setEstimates(const std::vector<double>& values) {
  std::size_t expected = 0;
  for (const auto& vertex : vertices_) expected += static_cast<std::size_t>(vertex->estimateSize());
  if (values.size() != expected)
    throw Error("setEstimates: the graph's vertices hold " + std::to_string(expected) + " values, got " +
                std::to_string(values.size()));
  std::size_t next = 0;
  for (const auto& vertex : vertices_) {
    vertex->setEstimate(values.data() + next);
    next += static_cast<std::size_t>(vertex->estimateSize());
  }
}

}  // namespace lrsvo
