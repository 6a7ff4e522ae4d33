// sortEdges() against std::sort with the filtration order.

#include <pcl/tda/search/radius_edges.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace pcl::tda;

namespace {

/** \a n random edges: values from a handful of tied values (0 and -0 among them),
 * negative ones, tiny and huge ones, or spread; ends below \a vertices. */
std::vector<FilteredEdge>
randomEdges (std::mt19937& random, std::size_t n, std::uint32_t vertices)
{
  std::uniform_int_distribution<std::uint32_t> vertex (0, vertices - 1);
  std::uniform_real_distribution<double> spread (0.0, 0.01);
  const std::vector<double> tied{0.0, -0.0, 0.005, 1e-300, -2.5, 1e300};
  std::vector<FilteredEdge> edges;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t a = vertex (random), b = vertex (random);
    if (a == b)
      b = (b + 1) % vertices;
    const double value =
        random() % 4 == 0 ? tied[random() % tied.size()] : spread (random);
    edges.push_back ({std::min (a, b), std::max (a, b), value});
  }
  return edges;
}

bool
sameEdges (const std::vector<FilteredEdge>& a, const std::vector<FilteredEdge>& b)
{
  return std::equal (
      a.begin(), a.end(), b.begin(), b.end(), [] (const auto& x, const auto& y) {
        return x.source == y.source && x.target == y.target && x.value == y.value;
      });
}

} // namespace

// Sizes around the chunks of the parallel passes, 1 to 3 threads, ties, signed
// zeros and negative values: the same order as std::sort's, edge for edge.
TEST (EdgeSort, SameOrderAsStdSort)
{
  std::mt19937 random (47);
  for (const std::size_t n :
       {0ul, 1ul, 2ul, 17ul, 1000ul, 65535ul, 65536ul, 131073ul, 300000ul}) {
    const std::vector<FilteredEdge> edges =
        randomEdges (random, n, n < 100 ? 10 : 100000);
    std::vector<FilteredEdge> expected = edges;
    std::stable_sort (expected.begin(), expected.end(), edgeFiltrationLess);
    for (const unsigned int threads : {1u, 2u, 3u}) {
      std::vector<FilteredEdge> sorted = edges;
      sortEdges (sorted, threads);
      EXPECT_TRUE (sameEdges (sorted, expected))
          << n << " edges, " << threads << " threads";
    }
  }
}

// Values that differ only in their lowest bits, or only in their highest: each byte
// of the values decides somewhere.
TEST (EdgeSort, EveryByteOfTheValuesCounts)
{
  std::mt19937 random (53);
  std::vector<FilteredEdge> edges;
  for (std::uint32_t i = 0; i < 5000; ++i) {
    const double near_one = 1.0 + static_cast<double> (random() % 1000) *
                                      std::numeric_limits<double>::epsilon();
    const double scaled = std::ldexp (1.0, static_cast<int> (random() % 200) - 100);
    edges.push_back ({i, i + 1, i % 2 ? near_one : scaled});
  }
  std::vector<FilteredEdge> expected = edges;
  std::sort (expected.begin(), expected.end(), edgeFiltrationLess);
  sortEdges (edges, 2);
  EXPECT_TRUE (sameEdges (edges, expected));
}
