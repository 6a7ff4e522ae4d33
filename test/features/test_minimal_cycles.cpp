/** Minimal 1-cycles (thesis Alg 5.15) and the projected polygon they rely on: the
 * worked example of Sec 5.4.2, an annulus, and independence of engine, order and
 * threads. */
#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/features/minimal_cycles.h>
#include <pcl/tda/features/projected_polygon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using pcl::tda::FilteredComplex;
using pcl::tda::FilteredEdge;
using pcl::tda::Point3d;
using pcl::tda::SimplexIndex;

TEST (ProjectedPolygon, SquareInsideAreaAndCrossings)
{
  const std::vector<Point3d> points{{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
  const pcl::tda::ProjectedPolygon square (points, {0, 1, 2, 3});
  EXPECT_NEAR (square.area(), 4.0, 1e-12);
  EXPECT_NEAR (std::abs (square.normal().z()), 1.0, 1e-9);
  EXPECT_TRUE (square.contains (square.project ({1.0, 1.0, 1.0})));
  EXPECT_TRUE (square.contains (square.project ({0.1, 1.9, 5.0}))); // any height
  EXPECT_FALSE (square.contains (square.project ({2.5, 1.0, 1.0})));
  EXPECT_FALSE (square.contains (square.project ({-0.1, -0.1, 1.0})));
  const Eigen::Vector2d center = square.project ({1.0, 1.0, 1.0});
  EXPECT_EQ (square.crossings (center.y()).size(), 2u);
}

TEST (ProjectedPolygon, NonConvexEvenOddRule)
{
  // A U shape: the notch between the arms is outside.
  const std::vector<Point3d> points{{0, 0, 0},
                                    {3, 0, 0},
                                    {3, 3, 0},
                                    {2, 3, 0},
                                    {2, 1, 0},
                                    {1, 1, 0},
                                    {1, 3, 0},
                                    {0, 3, 0}};
  const pcl::tda::ProjectedPolygon u (points, {0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_NEAR (u.area(), 7.0, 1e-12);
  EXPECT_TRUE (u.contains (u.project ({0.5, 2.0, 0.0})));
  EXPECT_TRUE (u.contains (u.project ({2.5, 2.0, 0.0})));
  EXPECT_FALSE (u.contains (u.project ({1.5, 2.0, 0.0})));
}

/** The neighbours of every vertex of \a complex. */
pcl::tda::EdgeAdjacency
adjacencyOf (const FilteredComplex& complex)
{
  return pcl::tda::buildEdgeAdjacency (complex.numVertices(), complex.edges());
}

/** The example of thesis Sec 5.4.2 (Fig 5.7-5.9): vertices a..h (0..7), 12 edges, 4
 * triangles, beta_0 = beta_1 = 1. The edge values put the negative edges
 * {ab, ad, bc, be, eh, eg, df} and the positive ones {bd, ce, gh, dg, fg} as the
 * thesis lists them; the positions lay the vertices out in a plane, with the hole
 * in the middle of d-b-e-g. */
enum Vertex : SimplexIndex { A, B, C, D, E, F, G, H };

FilteredComplex
thesisExample ()
{
  const std::vector<FilteredEdge> edges{{A, B, 1.0},
                                        {A, D, 2.0},
                                        {B, D, 2.5},
                                        {B, C, 4.0},
                                        {B, E, 5.0},
                                        {C, E, 6.0},
                                        {E, H, 7.0},
                                        {E, G, 8.0},
                                        {G, H, 9.0},
                                        {D, F, 10.0},
                                        {D, G, 11.0},
                                        {F, G, 12.0}};
  return FilteredComplex::fromLists (
      8, edges, {{A, B, D}, {B, C, E}, {E, G, H}, {D, F, G}});
}

const std::vector<Point3d> THESIS_POSITIONS{{0, 2, 0},     // a
                                            {1, 2, 0},     // b
                                            {2.2, 2.2, 0}, // c
                                            {0, 1, 0},     // d
                                            {2, 1, 0},     // e
                                            {0, 0, 0},     // f
                                            {1, 0, 0},     // g
                                            {2.2, 0, 0}};  // h

/** The cycle's vertices rotated to start at its smallest one and oriented so that
 * the second is the smaller neighbour: equal cycles compare equal. */
std::vector<SimplexIndex>
canonicalCycle (std::vector<SimplexIndex> cycle)
{
  std::rotate (
      cycle.begin(), std::min_element (cycle.begin(), cycle.end()), cycle.end());
  if (cycle.size() > 2 && cycle.back() < cycle[1])
    std::reverse (cycle.begin() + 1, cycle.end());
  return cycle;
}

/** The initial cycles of every essential class (thesis Alg 5.15, step 1). */
std::vector<pcl::tda::InitialCycle>
essentialCycles (const FilteredComplex& complex,
                 const pcl::tda::PersistenceResult& result)
{
  return pcl::tda::classCycles (
      complex, result.edge_positive, pcl::tda::essentialEdges (result));
}

TEST (MinimalCycles, ThesisExampleEveryEngine)
{
  const FilteredComplex complex = thesisExample();
  for (const auto& entry : pcl::tda::persistenceEngines()) {
    SCOPED_TRACE (entry.name);
    const pcl::tda::PersistenceResult result =
        pcl::tda::computePersistence (complex, entry.engine);
    // sigma- = {ab, ad, bc, be, eh, eg, df}, sigma+ = {bd, ce, gh, dg, fg}.
    const std::vector<std::uint8_t> positive{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 1, 1};
    EXPECT_EQ (result.edge_positive, positive);
    // dg (edge 10) is the one unpaired positive edge.
    EXPECT_EQ (pcl::tda::essentialEdges (result), std::vector<SimplexIndex>{10});
    const auto cycles = pcl::tda::minimalCycles (complex,
                                                 essentialCycles (complex, result),
                                                 THESIS_POSITIONS,
                                                 adjacencyOf (complex),
                                                 0.6,
                                                 1);
    ASSERT_EQ (cycles.size(), 1u);
    EXPECT_EQ (cycles[0].class_edge, 10u);
    // The initial cycle d-a-b-e-g shrinks by the chord bd to d-b-e-g.
    EXPECT_EQ (canonicalCycle (cycles[0].vertices), canonicalCycle ({D, B, E, G}));
    // The hole around (1, 1), whose empty disk has radius 1, up to the grid's cell
    // (an eighth of the largest edge value, 12, here).
    EXPECT_GT (cycles[0].clearance, 0.6);
    EXPECT_LE (cycles[0].clearance, 1.0);
  }
}

TEST (MinimalCycles, PersistentClassesAreBornByTheRadiusAndAliveAfter)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<FilteredEdge> edges;
  for (SimplexIndex e = 0; e < 6; ++e)
    edges.push_back ({e, e + 1, 0.1 * (e + 1)});
  const std::vector<std::uint8_t> positive{0, 1, 1, 0, 1, 1};
  const std::vector<double> death{0.1, 0.25, inf, 0.4, 0.9, inf};
  // Edge 5 is born after the radius 0.5, edge 1 dies at 0.25, edges 0 and 3 are
  // negative.
  EXPECT_EQ (pcl::tda::persistentClassEdges (edges, positive, death, 0.5, 0.8),
             (std::vector<SimplexIndex>{2, 4}));
  EXPECT_EQ (pcl::tda::persistentClassEdges (edges, positive, death, 0.5, 0.2),
             (std::vector<SimplexIndex>{1, 2, 4}));
  EXPECT_EQ (pcl::tda::persistentClassEdges (edges, positive, death, 0.5, 0.95),
             (std::vector<SimplexIndex>{2}));
  EXPECT_EQ (pcl::tda::persistentClassEdges (edges, positive, death, 0.7, 0.95),
             (std::vector<SimplexIndex>{2, 5}));
}

TEST (MinimalCycles, NoEmptyRegionWideEnoughGivesNoCycle)
{
  const FilteredComplex complex = thesisExample();
  const auto result = pcl::tda::computePersistence (complex);
  EXPECT_TRUE (pcl::tda::minimalCycles (complex,
                                        essentialCycles (complex, result),
                                        THESIS_POSITIONS,
                                        adjacencyOf (complex),
                                        1.5)
                   .empty());
}

/** Points of an annulus (inner radius 1, outer 2) on a jittered polar grid, in a
 * shuffled order when \a shuffle_seed is not 0, with the complex of radius r. */
struct Annulus {
  std::vector<Point3d> positions;
  FilteredComplex complex;
};

Annulus
makeAnnulus (unsigned shuffle_seed)
{
  std::mt19937 rng (7);
  std::uniform_real_distribution<double> jitter (-0.02, 0.02);
  std::vector<Point3d> points;
  for (int ring = 0; ring <= 10; ++ring) {
    const double radius = 1.0 + ring * 0.1;
    const int count = static_cast<int> (2.0 * M_PI * radius / 0.1);
    for (int k = 0; k < count; ++k) {
      const double angle = 2.0 * M_PI * k / count;
      points.push_back ({radius * std::cos (angle) + jitter (rng),
                         radius * std::sin (angle) + jitter (rng),
                         jitter (rng)});
    }
  }
  if (shuffle_seed != 0) {
    std::mt19937 shuffler (shuffle_seed);
    std::shuffle (points.begin(), points.end(), shuffler);
  }
  const double r = 0.25;
  std::vector<FilteredEdge> edges;
  for (SimplexIndex i = 0; i < points.size(); ++i)
    for (SimplexIndex j = i + 1; j < points.size(); ++j)
      if (pcl::tda::distance (points[i], points[j]) <= r)
        edges.push_back ({i, j, pcl::tda::distance (points[i], points[j])});
  std::vector<std::array<SimplexIndex, 3>> triangles;
  std::vector<std::vector<SimplexIndex>> near (points.size());
  for (const FilteredEdge& e : edges)
    near[e.source].push_back (e.target);
  for (SimplexIndex i = 0; i < points.size(); ++i)
    for (const SimplexIndex j : near[i])
      for (const SimplexIndex k : near[i])
        if (j < k && pcl::tda::distance (points[j], points[k]) <= r)
          triangles.push_back ({i, j, k});
  return {points, FilteredComplex::fromLists (points.size(), edges, triangles)};
}

/** The rim's points as positions, sorted, so that results in different vertex
 * numberings compare. */
std::vector<Point3d>
rimPositions (const pcl::tda::MinimalCycle& cycle,
              const std::vector<Point3d>& positions)
{
  std::vector<Point3d> rim;
  for (const SimplexIndex v : cycle.vertices)
    rim.push_back (positions[v]);
  std::sort (rim.begin(), rim.end());
  return rim;
}

/** The minimal cycles of the annulus' essential classes, around empty disks of
 * radius 0.5 at least. */
std::vector<pcl::tda::MinimalCycle>
annulusRims (const Annulus& annulus, unsigned threads)
{
  return pcl::tda::minimalCycles (
      annulus.complex,
      essentialCycles (annulus.complex, pcl::tda::computePersistence (annulus.complex)),
      annulus.positions,
      adjacencyOf (annulus.complex),
      0.5,
      threads);
}

TEST (MinimalCycles, AnnulusRimHugsTheHoleForAnyOrderAndThreads)
{
  const Annulus annulus = makeAnnulus (0);
  const auto cycles = annulusRims (annulus, 1);
  ASSERT_EQ (cycles.size(), 1u);
  // Every rim point is on the inner ring (radius 1 +- jitter) and the rim goes all
  // the way round: about 2 pi / 0.25 edges at least.
  for (const SimplexIndex v : cycles[0].vertices)
    EXPECT_LT (std::hypot (annulus.positions[v][0], annulus.positions[v][1]), 1.05);
  EXPECT_GE (cycles[0].vertices.size(), 26u);
  EXPECT_NEAR (cycles[0].clearance, 1.0, 0.08);
  const auto expected = rimPositions (cycles[0], annulus.positions);
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Annulus shuffled = makeAnnulus (seed);
    for (const unsigned threads : {1u, 2u, 4u}) {
      const auto again = annulusRims (shuffled, threads);
      ASSERT_EQ (again.size(), 1u);
      // fromLists keeps the vertex numbering of the input, so the rim is compared
      // by position.
      EXPECT_EQ (rimPositions (again[0], shuffled.positions), expected);
    }
  }
}

/** The points of the border of the rectangle [x0, x1] x [y0, y1] of a grid of
 * \a width columns, in order around it. */
std::vector<SimplexIndex>
rectangleLoop (int x0, int y0, int x1, int y1, int width)
{
  std::vector<SimplexIndex> loop;
  const auto id = [width] (int x, int y) {
    return static_cast<SimplexIndex> (y * width + x);
  };
  for (int x = x0; x < x1; ++x)
    loop.push_back (id (x, y0));
  for (int y = y0; y < y1; ++y)
    loop.push_back (id (x1, y));
  for (int x = x1; x > x0; --x)
    loop.push_back (id (x, y1));
  for (int y = y1; y > y0; --y)
    loop.push_back (id (x0, y));
  return loop;
}

TEST (MinimalCycles, ALongCycleNearlyTheSameAsAnEarlierOneIsNotSearchedAgain)
{
  // A plane grid of 300 x 260 points, step 1, joined to its 8 neighbours, with a
  // hole of radius 6 (its points kept, but no edge enters it). Three long initial
  // cycles around the hole: the grid's border (1116 points), the same border from
  // another start (all points shared: not searched), and the border of the lower
  // 300 x 221 points (1038 points, 66 % of them shared: searched).
  constexpr int WIDTH = 300, HEIGHT = 260;
  const Point3d centre{150.0, 100.0, 0.0};
  std::vector<Point3d> positions;
  for (int y = 0; y < HEIGHT; ++y)
    for (int x = 0; x < WIDTH; ++x)
      positions.push_back ({static_cast<double> (x), static_cast<double> (y), 0.0});
  const auto in_hole = [&] (SimplexIndex v) {
    return pcl::tda::distance (positions[v], centre) < 6.0;
  };
  std::vector<FilteredEdge> edges;
  for (int y = 0; y < HEIGHT; ++y)
    for (int x = 0; x < WIDTH; ++x)
      for (const auto& [dx, dy] :
           std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {1, 1}, {-1, 1}}) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || u >= WIDTH || v >= HEIGHT)
          continue;
        const auto a = static_cast<SimplexIndex> (y * WIDTH + x),
                   b = static_cast<SimplexIndex> (v * WIDTH + u);
        if (!in_hole (a) && !in_hole (b))
          edges.push_back ({a, b, pcl::tda::distance (positions[a], positions[b])});
      }
  const FilteredComplex complex =
      FilteredComplex::fromLists (positions.size(), edges, {});
  std::vector<SimplexIndex> border = rectangleLoop (0, 0, WIDTH - 1, HEIGHT - 1, WIDTH);
  std::vector<SimplexIndex> rotated = border;
  std::rotate (rotated.begin(), rotated.begin() + 100, rotated.end());
  const std::vector<pcl::tda::InitialCycle> initial{
      {border, 7}, {rotated, 9}, {rectangleLoop (0, 0, WIDTH - 1, 220, WIDTH), 11}};
  const auto cycles =
      pcl::tda::minimalCycles (complex, initial, positions, adjacencyOf (complex), 3.0);
  std::vector<SimplexIndex> classes;
  for (const auto& cycle : cycles) {
    classes.push_back (cycle.class_edge);
    for (const SimplexIndex v : cycle.vertices)
      EXPECT_LT (pcl::tda::distance (positions[v], centre), 8.0);
  }
  EXPECT_EQ (classes, (std::vector<SimplexIndex>{7, 11}));
}

} // namespace
