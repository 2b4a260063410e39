#pragma once

namespace lrsvo {

// Adds the edge types of lrsvo::edges to Registry<Edge>, and the vertex types
// they join (registerVertexTypes), so that graph files holding them can be read.
// Safe to call more than once and from several threads.
void registerEdgeTypes();

}  // namespace lrsvo
