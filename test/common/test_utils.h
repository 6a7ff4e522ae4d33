#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** A random filtered flag complex (or a random subset of its triangles) for
 * oracle tests. With \a integer_values the edge values are small integers, so
 * many simplices share a filtration value. */
inline FilteredComplex
randomComplex (std::mt19937& random,
               bool integer_values,
               bool all_triangles,
               std::size_t max_vertices = 18)
{
  const std::size_t n =
      std::uniform_int_distribution<std::size_t> (1, max_vertices) (random);
  const double density = std::uniform_real_distribution<double> (0.1, 0.9) (random);
  std::bernoulli_distribution keep_edge (density), keep_triangle (0.7);
  std::uniform_int_distribution<int> integer_value (0, 6);
  std::uniform_real_distribution<double> real_value (0.0, 1.0);

  std::vector<FilteredEdge> edges;
  std::vector<std::vector<bool>> adjacent (n, std::vector<bool> (n, false));
  for (SimplexIndex u = 0; u < n; ++u)
    for (SimplexIndex v = u + 1; v < n; ++v)
      if (keep_edge (random)) {
        const double value =
            integer_values ? integer_value (random) : real_value (random);
        edges.push_back ({u, v, value});
        adjacent[u][v] = adjacent[v][u] = true;
      }
  std::vector<std::array<SimplexIndex, 3>> triangles;
  for (SimplexIndex u = 0; u < n; ++u)
    for (SimplexIndex v = u + 1; v < n; ++v)
      for (SimplexIndex w = v + 1; w < n; ++w)
        if (adjacent[u][v] && adjacent[u][w] && adjacent[v][w] &&
            (all_triangles || keep_triangle (random)))
          triangles.push_back ({u, v, w});
  std::shuffle (edges.begin(), edges.end(), random);
  std::shuffle (triangles.begin(), triangles.end(), random);
  return FilteredComplex::fromLists (n, edges, triangles);
}

/** The k-th case of the standard random suite: varied sizes, ties, subsets. */
inline FilteredComplex
randomComplexCase (unsigned int k)
{
  std::mt19937 random (20261122u + k);
  return randomComplex (random, k % 2 == 0, k % 3 != 0);
}

/** Number of cases of the random suite (the issue asks for at least 1000). */
constexpr unsigned int RANDOM_CASES = 1200;

/** Edge and triangle ids of the filter of figure52Filter(). */
enum Figure52Edge : SimplexIndex { AB, AE, BE, AD, CD, AC, CE, BC };
enum Figure52Triangle : SimplexIndex { BCE, ACE, ABC, ACD, ABE };

/** The filter of thesis Fig 5.2: vertices a..e, then edges ab, ae, be, ad, cd, ac,
 * ce, bc (filter positions 5..12) and triangles bce, ace, abc, acd, abe (13..17);
 * each simplex's value is its position. */
inline FilteredComplex
figure52Filter ()
{
  enum { a, b, c, d, e };
  return FilteredComplex (5,
                          {{a, b, 5},
                           {a, e, 6},
                           {b, e, 7},
                           {a, d, 8},
                           {c, d, 9},
                           {a, c, 10},
                           {c, e, 11},
                           {b, c, 12}},
                          {{{7, 6, 2}, 13},
                           {{6, 5, 1}, 14},
                           {{7, 5, 0}, 15},
                           {{5, 4, 3}, 16},
                           {{2, 1, 0}, 17}});
}

/** The finite pairs of \a result as sorted (birth, death) positions in the global
 * filtration order, the form PHAT reports. */
inline std::vector<std::pair<std::int64_t, std::int64_t>>
globalPairs (const FilteredComplex& complex, const PersistenceResult& result)
{
  const auto order = complex.filtrationOrder();
  std::vector<std::int64_t> position[3];
  position[0].resize (complex.numVertices());
  position[1].resize (complex.numEdges());
  position[2].resize (complex.numTriangles());
  for (std::size_t g = 0; g < order.size(); ++g)
    position[order[g].dimension][order[g].index] = static_cast<std::int64_t> (g);
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (const auto& pair : result.pairs (complex))
    if (!pair.isEssential())
      pairs.emplace_back (position[pair.dimension][pair.birth_simplex],
                          position[pair.dimension + 1][pair.death_simplex]);
  std::sort (pairs.begin(), pairs.end());
  return pairs;
}

} // namespace test
} // namespace tda
} // namespace pcl
