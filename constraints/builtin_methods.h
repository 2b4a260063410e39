#pragma once

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

// Each constraint method adds itself to the registry from its own source file;
// builtin_methods.cpp calls them all (ConstraintMethod::addBuiltins).
void addNoConstraints(Registry<ConstraintMethod>& registry);
void addLogBarrier(Registry<ConstraintMethod>& registry);
void addGradientProjection(Registry<ConstraintMethod>& registry);
void addNloptMethods(Registry<ConstraintMethod>& registry);

}  // namespace lrsvo
