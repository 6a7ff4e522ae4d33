#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/point_cloud.h>

#include <gtest/gtest.h>

#include "complex_difference.h"
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** Expects a Vietoris-Rips builder of type \a Builder to report the progress of a
 * build of \a cloud at radius \a radius in thousandths, never backwards, ending at
 * 1000, with and without triangles, to build the same complex with a callback as
 * without, and to let a callback that throws cancel the build; on one thread at least
 * \a min_reports times. (Only OpenMP's master thread
 * reports from the parallel loops: on a busy machine the other threads may do all of
 * their work, so the count is checked on one thread, where it does not depend on the
 * machine.) */
template <typename Builder, typename CloudPtr>
void
expectReportsProgress (const CloudPtr& cloud, double radius, std::size_t min_reports)
{
  const int default_threads = omp_get_max_threads();
  for (const int threads : {1, default_threads})
    for (const int dimension : {1, 2}) {
      SCOPED_TRACE (testing::Message()
                    << "dimension " << dimension << ", " << threads << " threads");
      omp_set_num_threads (threads);
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
      // A callback that throws at any of its calls (a caller cancelling the build,
      // also from inside a parallel pass): the exception reaches the caller. (On
      // several threads, only the first call is sure to come.)
      const std::size_t calls_sure = threads == 1 ? seen.size() : 1;
      for (std::size_t k = 1; k <= calls_sure;
           k += std::max<std::size_t> (1, calls_sure / 7)) {
        std::size_t calls = 0;
        builder.setProgressCallback ([&calls, k] (std::size_t, std::size_t) {
          if (++calls == k)
            throw std::runtime_error ("cancelled");
        });
        FilteredComplex cancelled;
        EXPECT_THROW (builder.compute (cancelled), std::runtime_error) << "call " << k;
      }
      omp_set_num_threads (default_threads);
      ASSERT_FALSE (seen.empty());
      if (threads == 1) {
        EXPECT_GE (seen.size(), min_reports);
      }
      EXPECT_TRUE (std::is_sorted (seen.begin(), seen.end()));
      EXPECT_EQ (seen.back(), 1000u);
      EXPECT_EQ (complexDifference (plain, reported), "");
    }
}

} // namespace test
} // namespace tda
} // namespace pcl
