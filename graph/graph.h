#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "lrsvo/graph/edge.h"
#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// Owns vertices and edges. Vertex ids are unique; every edge must join
// vertices of this graph. Insertion order is kept (it is the file order).
class Graph {
 public:
  Graph() = default;
  Graph(const Graph&) = delete;
  Graph& operator=(const Graph&) = delete;
  Graph(Graph&&) = default;
  Graph& operator=(Graph&&) = default;

  // Throws lrsvo::Error on a duplicate id or a null vertex.
  template <typename V>
  V* addVertex(std::unique_ptr<V> vertex) {
    V* raw = vertex.get();
    insertVertex(std::move(vertex));
    return raw;
  }
  // Throws lrsvo::Error when a vertex slot is empty or names a vertex not in this graph.
  template <typename E>
  E* addEdge(std::unique_ptr<E> edge) {
    E* raw = edge.get();
    insertEdge(std::move(edge));
    return raw;
  }

  // Removes the vertex and every edge incident to it.
  void removeVertex(int id);
  void removeEdge(const Edge* edge);

  Vertex* vertex(int id) const;
  const std::vector<std::unique_ptr<Vertex>>& vertices() const { return vertices_; }
  const std::vector<std::unique_ptr<Edge>>& edges() const { return edges_; }
  bool empty() const { return vertices_.empty(); }

  // Sum of all edge costs (Ceres' convention, 1/2 rho(||r||^2) per edge),
  // evaluated on `threads` threads (>= 1) and added in edge order: the same
  // value for any count.
  double cost(int threads = 1) const;

  // Every vertex's estimate, one after another in vertex order: a start to
  // come back to with setEstimates (say, to solve again from it).
  std::vector<double> estimates() const;
  // Sets every vertex's estimate from values laid out as estimates() gives
  // them. Throws lrsvo::Error when their count is not that of estimates().
  void setEstimates(const std::vector<double>& values);

 private:
  void insertVertex(std::unique_ptr<Vertex> vertex);
  void insertEdge(std::unique_ptr<Edge> edge);

  std::vector<std::unique_ptr<Vertex>> vertices_;
  std::vector<std::unique_ptr<Edge>> edges_;
  std::unordered_map<int, Vertex*> byId_;
};

}  // namespace lrsvo
