#pragma once

#include <iosfwd>
#include <string>

#include "lrsvo/graph/graph.h"

namespace lrsvo {

// The plain-text graph file: one line per vertex and edge, g2o-like.
//
//   # comment
//   VERTEX <type tag> <id> <fixed 0|1> <marginalised 0|1> <estimate...>
//   EDGE <type tag> <vertex id>... <edge data: parameters, measurement,
//        information upper triangle, robust kernel (NONE | name delta)>
//   END <vertex count> <edge count>
//
// Numbers are written with 17 significant digits, so save -> load is exact.
// Types are looked up in Registry<Vertex> / Registry<Edge> by tag: lrsvo's
// own once registerVertexTypes(), registerEdgeTypes() (lrsvo/edges/edge_types.h)
// or registerConstraintTypes() has run, a user's own once registered.
void saveGraph(const Graph& graph, std::ostream& out);
void saveGraphFile(const Graph& graph, const std::string& path);

// Throws lrsvo::ParseError naming the source and line on malformed or
// truncated input, non-finite values, a missing END line, unknown tags, duplicate ids, and edges
// that name missing vertices.
Graph loadGraph(std::istream& in, const std::string& sourceName);
Graph loadGraphFile(const std::string& path);

}  // namespace lrsvo
