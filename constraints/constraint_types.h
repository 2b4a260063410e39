#pragma once

namespace lrsvo {

// Adds the constraint library's edge type (BarrierEdge) to Registry<Edge>, so
// that graph files holding it can be read. Safe to call more than once and
// from several threads.
void registerConstraintTypes();

}  // namespace lrsvo
