#include <pcl/tda/common/index_check.h>

#include <gtest/gtest.h>

namespace {

using pcl::tda::indicesAreValid;

TEST (IndexCheck, EveryPointOnceIsValid)
{
  EXPECT_TRUE (indicesAreValid ("Test::compute", 0, {}));
  EXPECT_TRUE (indicesAreValid ("Test::compute", 5, {}));
  EXPECT_TRUE (indicesAreValid ("Test::compute", 5, {4, 0, 2}));
  EXPECT_TRUE (indicesAreValid ("Test::compute", 5, {0, 1, 2, 3, 4}));
}

TEST (IndexCheck, OutOfRangeOrRepeatedIndicesAreRefused)
{
  EXPECT_FALSE (indicesAreValid ("Test::compute", 5, {0, 5}));
  EXPECT_FALSE (indicesAreValid ("Test::compute", 5, {-1}));
  EXPECT_FALSE (indicesAreValid ("Test::compute", 100, {50000000}));
  EXPECT_FALSE (indicesAreValid ("Test::compute", 0, {0}));
  EXPECT_FALSE (indicesAreValid ("Test::compute", 5, {0, 3, 1, 3}));
}

} // namespace
