// Tests of StoredColumns, the columns a coboundary reduction keeps: every column
// reads back as stored, also when the columns fill several blocks and one column is
// larger than a block.

#include <pcl/tda/common/coboundary_reduction.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

using pcl::tda::SimplexIndex;
using pcl::tda::StoredColumns;

TEST (StoredColumns, ColumnsReadBackAcrossBlocks)
{
  // 8 MiB blocks of 8-byte keys hold 1,048,576 keys; these columns fill about four.
  constexpr std::size_t NUM_EDGES = 12000;
  std::mt19937_64 random (42);
  std::uniform_int_distribution<std::size_t> length (0, 800);
  StoredColumns<std::uint64_t> stored (NUM_EDGES);
  std::vector<std::vector<std::uint64_t>> expected (NUM_EDGES);
  for (SimplexIndex edge = 0; edge < NUM_EDGES; edge += 2) {
    // Edge 1000's column is larger than a block.
    const std::size_t size = edge == 1000 ? 1200000 : length (random);
    for (std::size_t k = 0; k < size; ++k)
      expected[edge].push_back (random());
    stored.store (edge, expected[edge]);
  }
  for (SimplexIndex edge = 0; edge < NUM_EDGES; ++edge) {
    ASSERT_EQ (stored.has (edge), edge % 2 == 0) << edge;
    if (!stored.has (edge))
      continue;
    const auto [first, last] = stored.column (edge);
    EXPECT_EQ (std::vector<std::uint64_t> (first, last), expected[edge]) << edge;
  }
}
