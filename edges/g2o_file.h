#pragma once

#include <iosfwd>
#include <string>

#include "lrsvo/graph/graph.h"

namespace lrsvo {

// g2o's text format for pose graphs, one element per line:
//
//   # comment
//   VERTEX_SE2 <id> <x> <y> <theta>
//   VERTEX_SE3:QUAT <id> <x> <y> <z> <qx> <qy> <qz> <qw>
//   EDGE_SE2 <i> <j> <dx> <dy> <dtheta> <information upper triangle, 6 values>
//   EDGE_SE3:QUAT <i> <j> <x> <y> <z> <qx> <qy> <qz> <qw> <information upper triangle, 21 values>
//   FIX <id>...
//
// read into VertexSE2, VertexSE3Quat, EdgeSE2 and EdgeSE3Quat (conventions in
// docs/pose_graphs.md). The upper triangles are row-major (I11 I12 ... I1n
// I22 ...); SE3's is ordered translation then rotation. A FIX line follows
// the vertices it fixes.

// Throws lrsvo::ParseError naming the source and line on an unknown tag, a
// truncated line or trailing data, a malformed or non-finite number, a
// duplicate vertex id, an edge or FIX naming a missing vertex (or a vertex of
// another type), an information matrix that is not positive definite, and a
// quaternion off unit norm (VertexSE3Quat::kQuaternionNormTolerance).
Graph loadG2o(std::istream& in, const std::string& sourceName);
Graph loadG2oFile(const std::string& path);

// Writes vertices (each followed by FIX when fixed), then edges, numbers with
// 17 significant digits, so load -> save -> load -> save is byte-exact and
// every value is restored exactly. Throws lrsvo::Error on a vertex or edge of
// another type and on an edge with a robust kernel, which the format cannot hold;
// then nothing is written.
void saveG2o(const Graph& graph, std::ostream& out);
void saveG2oFile(const Graph& graph, const std::string& path);

}  // namespace lrsvo
