#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/point_cloud.h>

#include <gtest/gtest.h>

#include "complex_difference.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** Expects a Vietoris-Rips builder of type \a Builder to report the progress of a
 * build of \a cloud at radius \a radius in thousandths, at least \a min_reports
 * times, never backwards, ending at 1000, with and without triangles; and to build
 * the same complex with a callback as without. */
template <typename Builder, typename CloudPtr>
void
expectReportsProgress (const CloudPtr& cloud, double radius, std::size_t min_reports)
{
  for (const int dimension : {1, 2}) {
    SCOPED_TRACE (testing::Message() << "dimension " << dimension);
    Builder builder;
    builder.setInputCloud (cloud);
    builder.setRadius (radius);
    builder.setMaxDimension (dimension);
    FilteredComplex plain, reported;
    ASSERT_TRUE (builder.compute (plain));
    std::vector<std::size_t> seen;
    builder.setProgressCallback ([&seen] (std::size_t done, std::size_t total) {
      EXPECT_EQ (total, 1000u);
      seen.push_back (done);
    });
    ASSERT_TRUE (builder.compute (reported));
    ASSERT_GE (seen.size(), min_reports);
    EXPECT_TRUE (std::is_sorted (seen.begin(), seen.end()));
    EXPECT_EQ (seen.back(), 1000u);
    EXPECT_EQ (complexDifference (plain, reported), "");
  }
}

} // namespace test
} // namespace tda
} // namespace pcl
