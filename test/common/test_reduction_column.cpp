// Tests of ReductionColumn, the column under reduction of the cohomology engines:
// its sum and pivot equal those of a set summed over Z2, before and after it turns
// into a heap, including when the additions empty it again.

#include <pcl/tda/common/reduction_column.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

using pcl::tda::ReductionColumn;

namespace {

using Key = std::uint64_t;

/** Sorted, distinct random keys below \a range. */
std::vector<Key>
randomColumn (std::mt19937_64& random, std::size_t size, Key range)
{
  std::set<Key> keys;
  std::uniform_int_distribution<Key> key (0, range - 1);
  while (keys.size() < size)
    keys.insert (key (random));
  return {keys.begin(), keys.end()};
}

/** \a sum += \a column over Z2. */
void
addToSet (std::set<Key>& sum, const std::vector<Key>& column)
{
  for (const Key key : column)
    if (!sum.erase (key))
      sum.insert (key);
}

} // namespace

TEST (ReductionColumn, SumsAndPivotsLikeASetOverZ2)
{
  constexpr Key RANGE = 20000;
  constexpr std::size_t LONG = ReductionColumn<Key>::HEAP_FROM * 3;
  std::mt19937_64 random (7);
  std::uniform_int_distribution<std::size_t> short_length (0, 64);
  ReductionColumn<Key> column;
  std::size_t heap_cases = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Every third column starts long, so that most trials run as a heap.
    std::vector<Key> start =
        randomColumn (random, trial % 3 == 0 ? LONG : short_length (random), RANGE);
    std::set<Key> expected (start.begin(), start.end());
    column.assign (start);
    std::vector<std::vector<Key>> added;
    for (int step = 0; step < 80; ++step) {
      // Mostly short additions; some long ones that push it past HEAP_FROM; some
      // repeats of an earlier one that cancel keys already in.
      std::vector<Key> addend =
          step % 7 == 3 && !added.empty()
              ? added[random() % added.size()]
              : randomColumn (
                    random, step % 11 == 5 ? LONG / 2 : short_length (random), RANGE);
      addToSet (expected, addend);
      column.add (addend.data(), addend.data() + addend.size());
      added.push_back (addend);
      ASSERT_EQ (column.findPivot(), !expected.empty()) << trial << " " << step;
      if (!expected.empty()) {
        ASSERT_EQ (column.pivot(), *expected.begin()) << trial << " " << step;
      }
    }
    heap_cases += expected.size() > ReductionColumn<Key>::HEAP_FROM;
    EXPECT_EQ (column.sum(), std::vector<Key> (expected.begin(), expected.end()))
        << trial;
  }
  EXPECT_GT (heap_cases, 10u);
}

TEST (ReductionColumn, AHeapCancelledToNothingHasNoPivot)
{
  std::mt19937_64 random (3);
  const std::vector<Key> keys =
      randomColumn (random, ReductionColumn<Key>::HEAP_FROM + 10, 100000);
  std::vector<Key> start = keys;
  ReductionColumn<Key> column;
  column.assign (start);
  const std::vector<Key> one{keys.back() + 1};
  column.add (one.data(), one.data() + 1); // now a heap
  column.add (keys.data(), keys.data() + keys.size());
  ASSERT_TRUE (column.findPivot());
  EXPECT_EQ (column.pivot(), keys.back() + 1);
  column.add (one.data(), one.data() + 1);
  EXPECT_FALSE (column.findPivot());
  EXPECT_TRUE (column.sum().empty());
}
