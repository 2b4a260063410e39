#pragma once

namespace lrsvo {

// Adds the vertex types of lrsvo::vertices to Registry<Vertex>, so that graph
// files holding them can be read.
// Safe to call more than once and from several threads.
void registerVertexTypes();

}  // namespace lrsvo
