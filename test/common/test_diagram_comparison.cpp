#include <pcl/tda/common/diagram_comparison.h>
#include <pcl/exceptions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

using pcl::tda::compareDiagrams;
using pcl::tda::PersistenceDiagram;
using pcl::tda::PersistenceInterval;

constexpr double INF = std::numeric_limits<double>::infinity();

/** A diagram like a small point cloud's: H0 bars born at 0, one essential, H1 bars. */
PersistenceDiagram
sampleDiagram ()
{
  return {{0, 0.0, 0.125},
          {0, 0.0, 0.5},
          {0, 0.0, 0.5},
          {0, 0.0, 1.75},
          {0, 0.0, INF},
          {1, 0.25, 0.75},
          {1, 0.5, 0.625},
          {1, 2.0, INF},
          {2, 1.0, 1.5}};
}

PersistenceDiagram
scaled (PersistenceDiagram diagram, double factor)
{
  for (auto& interval : diagram) {
    interval.birth *= factor;
    interval.death *= factor;
  }
  return diagram;
}

void
expectSameIntervals (const PersistenceDiagram& expected,
                     const PersistenceDiagram& actual)
{
  ASSERT_EQ (expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ (expected[i].dimension, actual[i].dimension) << "interval " << i;
    EXPECT_EQ (expected[i].birth, actual[i].birth) << "interval " << i;
    EXPECT_EQ (expected[i].death, actual[i].death) << "interval " << i;
  }
}

TEST (DiagramComparison, IdenticalDiagramsAreEqual)
{
  const auto result = compareDiagrams (sampleDiagram(), sampleDiagram());
  EXPECT_TRUE (result.equal);
  EXPECT_EQ (9u, result.matched);
  EXPECT_TRUE (result.only_in_first.empty());
  EXPECT_TRUE (result.only_in_second.empty());
  EXPECT_EQ ("diagrams are equal: 9 intervals matched", result.summary());
}

TEST (DiagramComparison, EmptyDiagramsAreEqual)
{
  const auto result = compareDiagrams ({}, {});
  EXPECT_TRUE (result.equal);
  EXPECT_EQ (0u, result.matched);
}

TEST (DiagramComparison, OrderDoesNotMatter)
{
  std::mt19937 generator (7);
  for (int trial = 0; trial < 20; ++trial) {
    PersistenceDiagram permuted = sampleDiagram();
    std::shuffle (permuted.begin(), permuted.end(), generator);
    const auto result = compareDiagrams (sampleDiagram(), permuted);
    EXPECT_TRUE (result.equal) << result.summary();
    EXPECT_EQ (9u, result.matched);
  }
}

TEST (DiagramComparison, PerturbationWithinToleranceMatches)
{
  for (const double factor : {1.0 + 9e-6, 1.0 - 9e-6}) {
    const auto result =
        compareDiagrams (sampleDiagram(), scaled (sampleDiagram(), factor));
    EXPECT_TRUE (result.equal) << factor << ": " << result.summary();
    EXPECT_EQ (9u, result.matched);
  }
  // Ripser's float distances.
  PersistenceDiagram in_float = sampleDiagram();
  for (auto& interval : in_float) {
    interval.birth = static_cast<float> (interval.birth + 0.1 / 3);
    interval.death = static_cast<float> (interval.death + 0.1 / 3);
  }
  PersistenceDiagram in_double = sampleDiagram();
  for (auto& interval : in_double) {
    interval.birth += 0.1 / 3;
    interval.death += 0.1 / 3;
  }
  EXPECT_TRUE (compareDiagrams (in_double, in_float).equal);
}

TEST (DiagramComparison, PerturbationBeyondToleranceDoesNotMatch)
{
  PersistenceDiagram perturbed = sampleDiagram();
  perturbed[5].death *= 1.0 + 2e-5; // H1 [0.25, 0.75)
  const auto result = compareDiagrams (sampleDiagram(), perturbed);
  EXPECT_FALSE (result.equal);
  EXPECT_EQ (8u, result.matched);
  expectSameIntervals ({{1, 0.25, 0.75}}, result.only_in_first);
  expectSameIntervals ({perturbed[5]}, result.only_in_second);

  // A looser tolerance accepts it.
  EXPECT_TRUE (compareDiagrams (sampleDiagram(), perturbed, 1e-4).equal);
  // A birth beyond tolerance counts as well.
  perturbed = sampleDiagram();
  perturbed[6].birth = 0.5 * (1.0 - 2e-5);
  EXPECT_FALSE (compareDiagrams (sampleDiagram(), perturbed).equal);
}

TEST (DiagramComparison, ZeroAndNearZeroLengthIntervalsAreDropped)
{
  PersistenceDiagram with_zero = sampleDiagram();
  with_zero.push_back ({1, 0.3, 0.3});
  with_zero.push_back ({1, 0.4, 0.4 * (1.0 + 1e-6)});
  with_zero.push_back ({0, 0.0, 1e-300});
  PersistenceDiagram other_zero = sampleDiagram();
  other_zero.push_back ({2, 0.9, 0.9});
  const auto result = compareDiagrams (with_zero, other_zero);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (9u, result.matched);

  // A short interval beyond tolerance is kept.
  with_zero.push_back ({1, 0.4, 0.4 * (1.0 + 1e-4)});
  EXPECT_FALSE (compareDiagrams (with_zero, other_zero).equal);
}

// car6.pcd at degree 10: our H1 [0.10049934835, 0.10050039221) is 1.04e-5 of its
// death long, kept; Ripser prints it with 6 digits, [0.100499, 0.1005), 9.95e-6 long,
// dropped. Unmatched and within the tolerance of the diagonal, ours is dropped too;
// one twice as long is kept.
TEST (DiagramComparison, UnmatchedIntervalsWithinTheToleranceOfTheDiagonalAreDropped)
{
  PersistenceDiagram ours = sampleDiagram(), ripser = sampleDiagram();
  ours.push_back ({1, 0.10049934835423416, 0.10050039221228847});
  ripser.push_back ({1, 0.100499, 0.1005});
  pcl::tda::DiagramComparison result = compareDiagrams (ours, ripser);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (result.matched, sampleDiagram().size());
  result = compareDiagrams (ripser, ours);
  EXPECT_TRUE (result.equal) << result.summary();

  ours.push_back ({1, 0.1004993, 0.1005015});
  result = compareDiagrams (ours, ripser);
  EXPECT_FALSE (result.equal);
  expectSameIntervals ({{1, 0.1004993, 0.1005015}}, result.only_in_first);
}

TEST (DiagramComparison, AbsoluteFloorMatchesZeroWithTinyValues)
{
  const auto result = compareDiagrams ({{1, 0.0, 1.0}}, {{1, 1e-300, 1.0}});
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_FALSE (compareDiagrams ({{1, 0.0, 1.0}}, {{1, 1e-9, 1.0}}).equal);
}

// The floor scales with the diagrams: diagrams in units of 1e-20 compare as in
// metres (an absolute floor of 1e-12 matched every such value with every other, and
// dropped every finite interval as of length zero).
TEST (DiagramComparison, FloorScalesWithTheDiagrams)
{
  for (const double unit : {1.0, 1e-20, 1e-30, 1e20}) {
    const PersistenceDiagram ours{{0, 0.0, 0.5 * unit}, {1, 0.3 * unit, 0.4 * unit}};
    const PersistenceDiagram near{{0, 0.0, 0.500001 * unit},
                                  {1, 0.300001 * unit, 0.4 * unit}};
    const PersistenceDiagram off{{0, 0.0, 0.5 * unit}, {1, 0.3 * unit, 0.41 * unit}};
    const PersistenceDiagram missing{{0, 0.0, 0.5 * unit}};
    EXPECT_TRUE (compareDiagrams (ours, near).equal) << unit;
    EXPECT_FALSE (compareDiagrams (ours, off).equal) << unit;
    EXPECT_FALSE (compareDiagrams (ours, missing).equal) << unit;
    EXPECT_TRUE (compareDiagrams ({{0, 0.0, unit}}, {{0, 1e-15 * unit, unit}}).equal)
        << unit;
  }
}

TEST (DiagramComparison, EssentialDoesNotMatchFinite)
{
  const double max = std::numeric_limits<double>::max();
  const auto result = compareDiagrams ({{1, 0.2, INF}}, {{1, 0.2, max}});
  EXPECT_FALSE (result.equal);
  EXPECT_EQ (0u, result.matched);
  expectSameIntervals ({{1, 0.2, INF}}, result.only_in_first);
  expectSameIntervals ({{1, 0.2, max}}, result.only_in_second);
  EXPECT_TRUE (compareDiagrams ({{1, 0.2, INF}}, {{1, 0.2 + 1e-7, INF}}).equal);
}

TEST (DiagramComparison, DimensionMustAgree)
{
  const auto result = compareDiagrams ({{1, 0.2, 0.5}}, {{2, 0.2, 0.5}});
  EXPECT_FALSE (result.equal);
  expectSameIntervals ({{1, 0.2, 0.5}}, result.only_in_first);
  expectSameIntervals ({{2, 0.2, 0.5}}, result.only_in_second);
}

TEST (DiagramComparison, MultiplicityCounts)
{
  PersistenceDiagram more = sampleDiagram();
  more.push_back ({0, 0.0, 0.5}); // a third copy
  more.push_back ({3, 1.0, 2.0});
  auto result = compareDiagrams (more, sampleDiagram());
  EXPECT_FALSE (result.equal);
  EXPECT_EQ (9u, result.matched);
  expectSameIntervals ({{0, 0.0, 0.5}, {3, 1.0, 2.0}}, result.only_in_first);
  EXPECT_TRUE (result.only_in_second.empty());

  // Symmetric.
  result = compareDiagrams (sampleDiagram(), more);
  EXPECT_EQ (9u, result.matched);
  EXPECT_TRUE (result.only_in_first.empty());
  expectSameIntervals ({{0, 0.0, 0.5}, {3, 1.0, 2.0}}, result.only_in_second);
}

TEST (DiagramComparison, ThousandsOfUlpTiesMatchOneToOne)
{
  // H0 of a dense cloud: every bar born at 0, deaths on a few values and their
  // neighbours 1 ulp apart; the second tool rounds each death up by 1 ulp.
  std::mt19937 generator (12345);
  std::uniform_int_distribution<int> base (0, 9), ulps (0, 3);
  PersistenceDiagram first, second;
  for (int i = 0; i < 5000; ++i) {
    double death = 0.01 * (1 + base (generator));
    for (int k = ulps (generator); k > 0; --k)
      death = std::nextafter (death, 1.0);
    first.push_back ({0, 0.0, death});
    second.push_back ({0, 0.0, std::nextafter (death, 1.0)});
  }
  std::shuffle (second.begin(), second.end(), generator);
  auto result = compareDiagrams (first, second);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (5000u, result.matched);

  // One bar missing from the second diagram is found, and only that one.
  const PersistenceInterval missing = {0, 0.0, 0.2};
  first.push_back (missing);
  result = compareDiagrams (first, second);
  EXPECT_EQ (5000u, result.matched);
  expectSameIntervals ({missing}, result.only_in_first);
  EXPECT_TRUE (result.only_in_second.empty());
}

TEST (DiagramComparison, DenseDeathsWithinToleranceAllMatch)
{
  // Deaths 1e-7 apart, each shifted by 3e-6 (within 1e-5), births a few 1e-9 apart so
  // that the second diagram's (birth, death) order is not its death order: taking
  // the first acceptable partner in that order leaves 42 intervals unmatched.
  PersistenceDiagram first, second;
  for (int i = 0; i < 2000; ++i) {
    const double death = 1.0 + 1e-7 * i;
    first.push_back ({1, 0.5, death});
    second.push_back ({1, 0.5 * (1.0 + 1e-9 * (i % 7)), death + 3e-6});
  }
  const auto result = compareDiagrams (first, second);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (2000u, result.matched);
}

// Seen on rops_cloud.pcd against Ripser: taking the closest death first would pair
// 1.0 with 1.000004 and leave 1.0000135 without a partner; the maximum matching
// pairs 1.0 with 0.999991 instead.
TEST (DiagramComparison, ClosestFirstChoiceIsRepairedToAMaximumMatching)
{
  const PersistenceDiagram ours{{0, 0.0, 1.0}, {0, 0.0, 1.0000135}};
  const PersistenceDiagram theirs{{0, 0.0, 0.999991}, {0, 0.0, 1.000004}};
  const auto result = compareDiagrams (ours, theirs, 1e-5);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (result.matched, 2u);
  EXPECT_FALSE (compareDiagrams (ours, {{0, 0.0, 0.999991}, {0, 0.0, 0.999992}}).equal);
}

TEST (DiagramComparison, HundredThousandIntervalsCompareQuickly)
{
  // All H0 births equal and H1 births within tolerance of each other: a matching
  // that scans every candidate would take O(n^2).
  std::mt19937 generator (99);
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  PersistenceDiagram first, second;
  for (int i = 0; i < 50000; ++i) {
    const double h0_death = 0.01 + unit (generator);
    first.push_back ({0, 0.0, h0_death});
    second.push_back ({0, 0.0, static_cast<float> (h0_death)});
    const double h1_birth = 0.5 + 1e-7 * unit (generator);
    const double h1_death = h1_birth + 0.01 + unit (generator);
    first.push_back ({1, h1_birth, h1_death});
    second.push_back (
        {1, static_cast<float> (h1_birth), static_cast<float> (h1_death)});
  }
  std::shuffle (second.begin(), second.end(), generator);
  const auto result = compareDiagrams (first, second);
  EXPECT_TRUE (result.equal) << result.summary();
  EXPECT_EQ (100000u, result.matched);
}

TEST (DiagramComparison, SummaryListsDifferingIntervals)
{
  PersistenceDiagram perturbed = sampleDiagram();
  perturbed[5].death = 0.8; // H1 [0.25, 0.75) becomes [0.25, 0.8)
  perturbed.push_back ({2, 3.0, INF});
  const std::string summary = compareDiagrams (sampleDiagram(), perturbed).summary();
  EXPECT_EQ ("diagrams differ: 8 intervals matched\n"
             "1 only in the first (H1: 1)\n"
             "  H1 [0.25, 0.75)\n"
             "2 only in the second (H1: 1, H2: 1)\n"
             "  H1 [0.25, 0.8)\n"
             "  H2 [3, inf)",
             summary);
}

TEST (DiagramComparison, SummaryListsAtMostMaxListed)
{
  PersistenceDiagram many;
  for (int i = 0; i < 15; ++i)
    many.push_back ({0, 0.0, 1.0 + i});
  const auto result = compareDiagrams (many, {});
  EXPECT_EQ ("diagrams differ: 0 intervals matched\n"
             "15 only in the first (H0: 15)\n"
             "  H0 [0, 1)\n"
             "  H0 [0, 2)\n"
             "  H0 [0, 3)\n"
             "  ... and 12 more\n"
             "0 only in the second",
             result.summary (3));
}

TEST (DiagramComparison, RejectsBadToleranceAndNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW (compareDiagrams ({}, {}, -1e-5), pcl::BadArgumentException);
  EXPECT_THROW (compareDiagrams ({}, {}, 1.0), pcl::BadArgumentException);
  EXPECT_THROW (compareDiagrams ({}, {}, nan), pcl::BadArgumentException);
  EXPECT_THROW (compareDiagrams ({{0, 0.0, nan}}, {}), pcl::BadArgumentException);
  EXPECT_THROW (compareDiagrams ({}, {{0, nan, 1.0}}), pcl::BadArgumentException);
}

} // namespace
