// The registries hold every plugin the libraries ship from their first use on,
// with no static initialiser to rely on (a static link drops unnamed objects).
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/eval/study.h"
#include "lrsvo/graph/edge.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/robust_kernel.h"

namespace lrsvo {
namespace {

template <typename Product>
std::set<std::string> namesIn() {
  std::set<std::string> names;
  for (const auto& [name, entry] : Registry<Product>::instance().entries()) names.insert(name);
  return names;
}

TEST(Registries, HoldEveryBuiltInPluginFromTheirFirstUse) {
  EXPECT_EQ(namesIn<LinearSolver>(), (std::set<std::string>{"cholmod", "dense", "schur_cholmod", "schur_dense",
                                                            "schur_pcg", "schur_power_series"}));
  EXPECT_EQ(namesIn<OptimizationAlgorithm>(), (std::set<std::string>{"gn", "lm"}));
  EXPECT_EQ(namesIn<RobustKernel>(), (std::set<std::string>{"Cauchy", "Huber", "Tukey"}));
  EXPECT_EQ(namesIn<ConstraintMethod>(),
            (std::set<std::string>{"gradient_projection", "log_barrier", "nlopt_lbfgs", "nlopt_mma", "none"}));
  for (const auto& [name, entry] : Registry<LinearSolver>::instance().entries()) {
    EXPECT_FALSE(entry.description.empty()) << name;
    EXPECT_NE(entry.factory(), nullptr) << name;
  }
}

TEST(Registries, EachLibraryRegistersItsGraphFileTypesOnRequest) {
  registerEdgeTypes();  // and the vertex types its edges join
  registerConstraintTypes();
  registerEdgeTypes();  // a second call changes nothing
  const std::set<std::string> vertices = namesIn<Vertex>();
  const std::set<std::string> edges = namesIn<Edge>();
  for (const char* tag :
       {"POSE_SE3", "POINT3", "STEREO_EXTRINSIC", "STEREO_EXTRINSIC_RATE", "SCALE", "BAL_CAMERA", "VECTOR1", "VECTOR9"})
    EXPECT_TRUE(vertices.count(tag)) << tag;
  for (const char* tag : {"PROJECT_BASE", "PROJECT_SECONDARY", "PROJECT_SECONDARY_SCALED", "PROJECT_SECONDARY_DRIFTING",
                          "PROJECT_HELD_VIEW", "SCALE_PRIOR", "CENTRE_DISTANCE", "STEREO_EXTRINSIC_RATE_PRIOR",
                          "BAL_PROJECTION", "BOUND_BARRIER"})
    EXPECT_TRUE(edges.count(tag)) << tag;
}

TEST(Registries, ListThePapersStudiesInAFixedOrder) {
  std::vector<std::string> names;
  for (const Study& study : studies()) names.push_back(study.name);
  EXPECT_EQ(names, (std::vector<std::string>{"depth-distribution", "disparity", "epipolar", "init-altitude",
                                             "init-scale", "range-bias", "triangulation"}));
}

}  // namespace
}  // namespace lrsvo
