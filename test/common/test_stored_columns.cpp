// Tests of StoredColumns, the columns a coboundary reduction keeps: every column
// reads back as stored, also when the columns fill several blocks and one column is
// larger than a block, and when two threads store at once, the same edges too.

#include <pcl/tda/common/coboundary_reduction.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <thread>
#include <vector>

using pcl::tda::SimplexIndex;
using pcl::tda::StoredColumns;

TEST (StoredColumns, ColumnsReadBackAcrossBlocks)
{
  // 8 MiB blocks of 8-byte keys hold 1,048,576 keys; these columns fill about four.
  constexpr std::size_t NUM_EDGES = 12000;
  std::mt19937_64 random (42);
  std::uniform_int_distribution<std::size_t> length (0, 800);
  StoredColumns<std::uint64_t> stored (NUM_EDGES, 1);
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

TEST (StoredColumns, TwoThreadsStoreAtOnce)
{
  // Each thread stores every edge of its own (edge % 3 == its number) and every
  // edge % 3 == 2, with the same keys, as two threads of the reduction store the
  // coboundary of an edge both need.
  constexpr std::size_t NUM_EDGES = 30000;
  std::mt19937_64 random (7);
  std::uniform_int_distribution<std::size_t> length (0, 200);
  std::vector<std::vector<std::uint64_t>> expected (NUM_EDGES);
  for (auto& column : expected) {
    column.resize (length (random));
    for (auto& key : column)
      key = random();
  }
  StoredColumns<std::uint64_t> stored (NUM_EDGES, 2);
  const auto store = [&] (int thread) {
    for (SimplexIndex edge = 0; edge < NUM_EDGES; ++edge)
      if (edge % 3 == static_cast<SimplexIndex> (thread) || edge % 3 == 2)
        stored.store (edge, expected[edge], thread);
  };
  std::thread first (store, 0), second (store, 1);
  first.join();
  second.join();
  for (SimplexIndex edge = 0; edge < NUM_EDGES; ++edge) {
    ASSERT_TRUE (stored.has (edge)) << edge;
    const auto [begin, end] = stored.column (edge);
    EXPECT_EQ (std::vector<std::uint64_t> (begin, end), expected[edge]) << edge;
  }
}
