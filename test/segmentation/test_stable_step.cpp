// chooseStableStep(): the step rule of the automatic clustering distance and colour
// threshold, on counts whose steps are known.

#include <pcl/tda/segmentation/stable_step.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace {

using pcl::tda::chooseStableStep;
using pcl::tda::StableStep;
using Events = std::vector<std::pair<double, int>>;

/** Four objects that become whole at 1 and merge pairwise at 2, 3 and 8 (counts 4
 * on [1, 2), 3 on [2, 3), 2 on [3, 8), 1 from 8): the finest stable split is the 4
 * objects, the longest (not clearly) is the 2 left after the close ones merged. */
const Events CLOSE_OBJECTS = {
    {1.0, +1}, {1.0, +1}, {1.0, +1}, {1.0, +1}, {2.0, -1}, {3.0, -1}, {8.0, -1}};

StableStep
choose (const Events& events, double floor = 0.5, double max = 100.0)
{
  StableStep step;
  EXPECT_TRUE (chooseStableStep (events, floor, max, 1.5, step));
  return step;
}

} // namespace

TEST (StableStep, TakesTheFinestStableSplitWhenNoSplitIsClear)
{
  const StableStep step = choose (CLOSE_OBJECTS);
  EXPECT_EQ (step.count, 4u);
  EXPECT_DOUBLE_EQ (step.low, 1.0);
  EXPECT_DOUBLE_EQ (step.high, 2.0);
  EXPECT_FALSE (step.clear); // the split into 2 is longer
}

TEST (StableStep, TakesTheLongestSplitWhenClear)
{
  // 3 on [1, 1.6), 2 on [1.6, 10), 1 from 10: the split into 2 is over q times as
  // long (in log) as the split into 3.
  const Events events = {{1.0, +1}, {1.0, +1}, {1.0, +1}, {1.6, -1}, {10.0, -1}};
  const StableStep step = choose (events);
  EXPECT_EQ (step.count, 2u);
  EXPECT_DOUBLE_EQ (step.low, 1.6);
  EXPECT_DOUBLE_EQ (step.high, 10.0);
  EXPECT_TRUE (step.clear);
}

TEST (StableStep, FinestPreferenceTakesTheFinestStableSplitAlsoWhenALaterOneIsClear)
{
  // 3 on [1, 1.6), 2 on [1.6, 10), 1 from 10, as above: the split into 2 is clear,
  // but the split into 3 is stable and comes first.
  const Events events = {{1.0, +1}, {1.0, +1}, {1.0, +1}, {1.6, -1}, {10.0, -1}};
  StableStep step;
  ASSERT_TRUE (chooseStableStep (
      events, 0.5, 100.0, 1.5, step, pcl::tda::StableStepPreference::FINEST));
  EXPECT_EQ (step.count, 3u);
  EXPECT_DOUBLE_EQ (step.low, 1.0);
  EXPECT_DOUBLE_EQ (step.high, 1.6);
  EXPECT_FALSE (step.clear);
  // Without a stable split, as the other preference: one cluster.
  ASSERT_TRUE (chooseStableStep ({{1.0, +1}, {1.0, +1}, {1.2, -1}},
                                 0.5,
                                 100.0,
                                 1.5,
                                 step,
                                 pcl::tda::StableStepPreference::FINEST));
  EXPECT_EQ (step.count, 1u);
  EXPECT_DOUBLE_EQ (step.low, 1.2);
}

TEST (StableStep, EventsThatLeaveTheCountAsItWasDoNotEndAStep)
{
  // 2 on [1, 3): a component appears and another one goes at 1.2; 1 from 3.
  const Events events = {{1.0, +1}, {1.0, +1}, {1.2, +1}, {1.2, -1}, {3.0, -1}};
  for (const auto preference : {pcl::tda::StableStepPreference::CLEAR_OR_FINEST,
                                pcl::tda::StableStepPreference::FINEST}) {
    StableStep step;
    ASSERT_TRUE (chooseStableStep (events, 0.5, 4.0, 1.5, step, preference));
    EXPECT_EQ (step.count, 2u);
    EXPECT_DOUBLE_EQ (step.low, 1.0);
    EXPECT_DOUBLE_EQ (step.high, 3.0);
  }
}

TEST (StableStep, SplitsShorterThanTheGapRatioAreSkipped)
{
  // Fragments: 2 on [1, 1.2), then 3 objects on [1.2, 1.3) too short, 2 on [1.3, 4).
  const Events events = {{1.0, +1}, {1.0, +1}, {1.2, +1}, {1.3, -1}, {4.0, -1}};
  const StableStep step = choose (events);
  EXPECT_EQ (step.count, 2u);
  EXPECT_DOUBLE_EQ (step.low, 1.3);
  EXPECT_DOUBLE_EQ (step.high, 4.0);
  EXPECT_TRUE (step.clear);
}

TEST (StableStep, OneClusterWhenNoSplitIsStable)
{
  // 2 on [1, 1.4) only, then one cluster up to the end.
  const Events events = {{1.0, +1}, {1.0, +1}, {1.4, -1}};
  const StableStep step = choose (events);
  EXPECT_EQ (step.count, 1u);
  EXPECT_DOUBLE_EQ (step.low, 1.4);
  EXPECT_DOUBLE_EQ (step.high, 100.0);
  EXPECT_TRUE (step.clear); // far longer than the short split
}

TEST (StableStep, AStepCutShortAtTheEndCountsAsLongAsItIsSeen)
{
  // 3 on [1, 2) spans the gap ratio; 2 on [2, 100) is cut short at the end but is
  // still the longest split seen, and clearly so: it is taken.
  const Events events = {{1.0, +1}, {1.0, +1}, {1.0, +1}, {2.0, -1}};
  const StableStep step = choose (events);
  EXPECT_EQ (step.count, 2u);
  EXPECT_DOUBLE_EQ (step.low, 2.0);
  EXPECT_DOUBLE_EQ (step.high, 100.0);
  EXPECT_TRUE (step.clear);
}

TEST (StableStep, IndependentOfTheEventOrderAndOfTheUnit)
{
  std::mt19937 random (7);
  for (int trial = 0; trial < 50; ++trial) {
    Events events = CLOSE_OBJECTS;
    std::shuffle (events.begin(), events.end(), random);
    const double unit = std::pow (10.0, trial % 7 - 3);
    Events scaled = events;
    for (auto& event : scaled)
      event.first *= unit;
    const StableStep reference = choose (CLOSE_OBJECTS);
    const StableStep step = choose (scaled, 0.5 * unit, 100.0 * unit);
    EXPECT_EQ (step.count, reference.count);
    EXPECT_NEAR (step.low, reference.low * unit, 1e-12 * unit);
    EXPECT_NEAR (step.high, reference.high * unit, 1e-12 * unit);
    EXPECT_EQ (step.clear, reference.clear);
  }
}

TEST (StableStep, NoPositiveCount)
{
  StableStep step;
  EXPECT_FALSE (chooseStableStep ({}, 1.0, 2.0, 1.5, step));
}
