#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistent_components.h>
#include <pcl/tda/common/union_find.h>

#include <gtest/gtest.h>

#include "test_utils.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace pcl::tda;

namespace {

/** Components of the edges of value <= cut by a plain union-find over all edges,
 * as sorted point indices, sorted largest first and then by smallest index. */
std::vector<pcl::Indices>
bruteForceComponents (const FilteredComplex& complex, double cut)
{
  UnionFind components (complex.numVertices());
  for (const auto& edge : complex.edges())
    if (edge.value <= cut) {
      const auto a = components.find (edge.source), b = components.find (edge.target);
      if (a != b)
        components.linkRoots (a, b);
    }
  std::map<SimplexIndex, pcl::Indices> by_root;
  for (SimplexIndex v = 0; v < complex.numVertices(); ++v)
    by_root[components.find (v)].push_back (complex.pointIndices()[v]);
  std::vector<pcl::Indices> result;
  for (auto& [root, indices] : by_root) {
    std::sort (indices.begin(), indices.end());
    result.push_back (indices);
  }
  std::sort (result.begin(), result.end(), [] (const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : a[0] < b[0];
  });
  return result;
}

} // namespace

TEST (PersistentComponents, EqualBruteForceAtEveryCut)
{
  for (unsigned int k = 0; k < test::RANDOM_CASES; k += 2) {
    const FilteredComplex complex = test::randomComplexCase (k);
    const PersistenceResult h0 = computeH0Persistence (complex);
    for (const double cut : {-1.0, 0.0, 0.3, 2.0, 4.5, 1e9})
      ASSERT_EQ (persistentComponents (complex, h0, cut),
                 bruteForceComponents (complex, cut))
          << "case " << k << " cut " << cut;
  }
}

// Deaths 1, 2.5, 3 with steps of 1 (max 4): rounded up to 1, 3, 3; beyond the last
// step, at the max.
TEST (PersistentComponents, SteppedDiagramRoundsDeathsUp)
{
  const auto complex = FilteredComplex::fromLists (
      5, {{0, 1, 1.0}, {1, 2, 2.5}, {2, 3, 3.0}, {3, 4, 4.5}}, {});
  const PersistenceResult h0 = computeH0Persistence (complex);
  std::vector<double> deaths;
  for (const auto& interval : steppedH0Diagram (complex, h0, 4.0, 4))
    deaths.push_back (interval.death);
  std::sort (deaths.begin(), deaths.end());
  EXPECT_EQ (deaths,
             (std::vector<double>{
                 1.0, 3.0, 3.0, 4.0, std::numeric_limits<double>::infinity()}));
  EXPECT_EQ (steppedH0Diagram (complex, h0, 4.0, 0).size(),
             h0.diagram (complex, 0).size());
}
