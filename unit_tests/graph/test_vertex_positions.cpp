// VertexPositions (graph/vertex_positions.h): every vertex of the list found
// at its position, any other address (and none) not found.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/vertex_positions.h"
#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo::test {
namespace {

TEST(VertexPositions, FindsEveryVertexAtItsPositionAndNoOther) {
  // Sizes around powers of two, where the table's size steps.
  for (const int count : {0, 1, 2, 3, 1023, 1024, 1025, 20000}) {
    std::vector<std::unique_ptr<VertexPoint3>> owned, others;
    std::vector<const Vertex*> listed;
    for (int i = 0; i < count; ++i) {
      owned.push_back(std::make_unique<VertexPoint3>(i));
      others.push_back(std::make_unique<VertexPoint3>(i));
      listed.push_back(owned.back().get());
    }
    const VertexPositions positions(listed);
    for (int i = 0; i < count; ++i) {
      ASSERT_EQ(positions.find(listed[static_cast<std::size_t>(i)]), i) << count;
      ASSERT_EQ(positions.find(others[static_cast<std::size_t>(i)].get()), -1) << count;
    }
    EXPECT_EQ(positions.find(nullptr), -1) << count;
  }
}

}  // namespace
}  // namespace lrsvo::test
