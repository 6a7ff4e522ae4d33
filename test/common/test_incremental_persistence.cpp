#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/incremental_persistence.h>
#include <pcl/tda/common/persistence_engines.h>

#include <gtest/gtest.h>

#include "test_utils.h"

using namespace pcl::tda;
using namespace pcl::tda::test;

// Thesis Sec 5.2.3, the example of Alg 5.9-5.11 on the filter of Fig 5.2, with the
// table states the text gives after each triangle.
TEST (IncrementalPersistence, ThesisExampleTableStates)
{
  const FilteredComplex complex = figure52Filter();
  const PersistenceResult h0 = computeH0Persistence (complex);
  IncrementalCycleTable table (complex, h0.edge_positive);

  // bce: Lambda = {bc, ce, be}, i = 12: stored in the free slot T[12].
  EXPECT_EQ (table.addTriangle (BCE), BC);
  EXPECT_EQ (table.cycle (BC), (CycleSet{BE, CE, BC}));
  EXPECT_EQ (table.death (BC), BCE);
  // ace: Lambda = {ce, ac}, i = 11: stored in T[11].
  EXPECT_EQ (table.addTriangle (ACE), CE);
  EXPECT_EQ (table.cycle (CE), (CycleSet{AC, CE}));
  // abc: Lambda = {bc, ac} collides at T[12], then {ce, ac, be} at T[11]; {be}
  // goes to T[7].
  EXPECT_EQ (table.addTriangle (ABC), BE);
  EXPECT_EQ (table.cycle (BE), (CycleSet{BE}));
  EXPECT_EQ (table.death (BE), ABC);
  // acd: Lambda = {ac} in T[10].
  EXPECT_EQ (table.addTriangle (ACD), AC);
  EXPECT_EQ (table.cycle (AC), (CycleSet{AC}));
  // abe: Lambda + Lambda^i is empty: a positive triangle.
  EXPECT_EQ (table.addTriangle (ABE), INVALID_SIMPLEX);
  EXPECT_FALSE (table.isOccupied (AB));

  // beta_1 = positive edges - negative triangles = 4 - 4 = 0.
  const PersistenceResult result =
      computePersistence (complex, PersistenceEngine::INCREMENTAL);
  EXPECT_EQ (std::count (result.edge_positive.begin(), result.edge_positive.end(), 1),
             4);
  EXPECT_EQ (
      std::count (result.triangle_positive.begin(), result.triangle_positive.end(), 0),
      4);
}
