#include <pcl/tda/common/fast_incremental_persistence.h>
#include <pcl/tda/common/h0_persistence.h>

#include <gtest/gtest.h>

#include "test_utils.h"

using namespace pcl::tda;
using namespace pcl::tda::test;

namespace {

bool
hasUpdate (const FastIncrementalCycleTable& table, SimplexIndex edge, SimplexIndex slot)
{
  const auto& list = table.updateList (edge);
  return std::find (list.begin(), list.end(), slot) != list.end();
}

} // namespace

// Thesis Sec 5.3.4 and Fig 5.4: fast incremental persistence on the filter of
// Fig 5.2, with the hash table states the text gives after each triangle.
TEST (FastIncrementalPersistence, ThesisExampleTableStates)
{
  const FilteredComplex complex = figure52Filter();
  const PersistenceResult h0 = computeH0Persistence (complex);
  FastIncrementalCycleTable table (complex, h0.edge_positive);

  // bce: Lambda = {be, ce, bc}, i = 12 free: T[12] = {be, ce}; be and ce get 12 in
  // their update lists.
  EXPECT_EQ (table.addTriangle (BCE), BC);
  EXPECT_EQ (table.cycle (BC), (CycleSet{BE, CE}));
  EXPECT_TRUE (hasUpdate (table, BE, BC));
  EXPECT_TRUE (hasUpdate (table, CE, BC));
  // ace: Lambda = {ac, ce}, i = 11 free: T[11] = {ac}; the update replaces ce by ac
  // in T[12].
  EXPECT_EQ (table.addTriangle (ACE), CE);
  EXPECT_EQ (table.cycle (CE), (CycleSet{AC}));
  EXPECT_EQ (table.cycle (BC), (CycleSet{BE, AC}));
  // abc: Lambda = {ac, bc} collides at T[12]: Lambda^c = {ac}, plus T[12] = {be}:
  // one sum, T[7] takes j = 15 and the update removes be from T[12].
  EXPECT_EQ (table.addTriangle (ABC), BE);
  EXPECT_TRUE (table.cycle (BE).empty());
  EXPECT_EQ (table.death (BE), ABC);
  EXPECT_EQ (table.cycle (BC), (CycleSet{AC}));
  // acd: Lambda = {ac}, T[10] free; the update reaches slots 11 and 12 and removes
  // ac from both.
  EXPECT_EQ (table.addTriangle (ACD), AC);
  EXPECT_TRUE (table.cycle (AC).empty());
  EXPECT_TRUE (table.cycle (CE).empty());
  EXPECT_TRUE (table.cycle (BC).empty());
  // abe closes a 2-cycle.
  EXPECT_EQ (table.addTriangle (ABE), INVALID_SIMPLEX);
}
