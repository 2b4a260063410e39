#pragma once

#include <iosfwd>
#include <string>

#include "graph/graph.h"

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
// Types are looked up in Registry<Vertex> / Registry<Edge> by tag, so a
// user's own types load once their library registers them.
void saveGraph(const Graph& graph, std::ostream& out);
void saveGraphFile(const Graph& graph, const std::string& path);

// Throws lrsvo::ParseError naming the source and line on malformed or
// truncated input, non-finite values, a missing END line, unknown tags, duplicate ids, and edges
// that name missing vertices.
Graph loadGraph(std::istream& in, const std::string& sourceName);
Graph loadGraphFile(const std::string& path);

}  // namespace lrsvo
