#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/large_vector.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/common/spanning_forest.h>
#include <pcl/tda/common/union_find.h>
#include <pcl/tda/search/boruvka_forest.h>
#include <pcl/tda/search/complex_size.h>
#include <pcl/tda/search/radius_edges.h>
#include <pcl/tda/search/uniform_grid.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Candidate pairs per point below which radiusGraphSpanningForest() lists a
 * scale's edges without looking at a finer scale first. */
constexpr double SPANNING_FOREST_PAIRS_PER_POINT = 128.0;

/** \brief Pairs per point that radiusGraphSpanningForest() looks at, at most, to
 * count a scale's pairs across components before it takes Borůvka's searches for the
 * rest of the forest instead. */
constexpr double SPANNING_FOREST_VISITS_PER_POINT = 256.0;

/** \brief Most scales radiusGraphSpanningForest() looks at (the radius and its
 * halves): where many points lie closer than any scale (copies apart by a rounding
 * error), no halving makes the pairs few. */
constexpr std::size_t MAX_SPANNING_FOREST_SCALES = 32;

/** \brief The cell sizes at which radiusGraphSpanningForest() looks for edges,
 * finest first: \a radius, then its halves while a UniformGrid of the last one (built
 * with \a threads) has more than SPANNING_FOREST_PAIRS_PER_POINT candidate pairs per
 * point, at most MAX_SPANNING_FOREST_SCALES of them. */
std::vector<double>
spanningForestScales (const std::vector<Point3d>& points,
                      double radius,
                      unsigned int threads);

/** \brief The ids of \a points sorted by position (x, y, z), then id: the copies of
 * a point come together, in increasing id. */
std::vector<std::uint32_t>
idsByPosition (const std::vector<Point3d>& points);

/** \brief The first step of radiusGraphSpanningForest(): joins the copies of each
 * point (equal coordinates) as Kruskal would, since their pairs have length 0 and come
 * first in filtration order: a pair of copies that passes \a accept and joins two
 * components, taken by increasing ends. With a test that accepts every pair, a
 * point's k copies cost k steps, not k^2 pairs.
 * \param[in,out] components the components, joined
 * \param[out] forest the edges taken, in filtration order
 * \return one point per position, for choosing the scales */
template <typename Accept>
std::vector<Point3d>
joinCopies (const std::vector<Point3d>& points,
            const Accept& accept,
            UnionFind& components,
            std::vector<FilteredEdge>& forest)
{
  const std::vector<std::uint32_t> ids = idsByPosition (points);
  std::vector<Point3d> positions;
  for (std::size_t first = 0, last = 0; first < ids.size(); first = last) {
    while (last < ids.size() && points[ids[last]] == points[ids[first]])
      ++last;
    positions.push_back (points[ids[first]]);
    std::size_t joins = 0;
    for (std::size_t i = first; i < last && joins + 1 < last - first; ++i)
      for (std::size_t j = i + 1; j < last; ++j) {
        const std::uint32_t a = components.find (ids[i]), b = components.find (ids[j]);
        if (a != b && accept (ids[i], ids[j])) {
          components.linkRoots (a, b);
          forest.push_back ({ids[i], ids[j], 0.0});
          ++joins;
        }
      }
  }
  std::sort (forest.begin(), forest.end(), edgeFiltrationLess);
  return positions;
}

/** \brief The components of a spanning forest under construction as the point order
 * of a UniformGrid meets them, so that pairs of points already joined are skipped a
 * run at a time. */
class ComponentRuns {
public:
  /** \brief Reads the component of each of the \a num_points points from
   * \a components, and the runs of \a grid (which must outlive this object). */
  ComponentRuns (const UniformGrid& grid,
                 UnionFind& components,
                 std::size_t num_points);

  /** \brief Calls \a visit(a, b) for the candidate pairs of cell \a cell (as
   * UniformGrid::forEachCandidatePair()) whose points lie in different components;
   * calls \a keep_going() before each point of the cell and stops when it returns
   * false. */
  template <typename Visit, typename KeepGoing>
  void
  forEachPairAcross (std::size_t cell, Visit visit, KeepGoing keep_going) const
  {
    for (std::uint32_t i = grid_.cellBegin (cell); i < grid_.cellBegin (cell + 1);
         ++i) {
      if (!keep_going())
        return;
      const std::uint32_t a = grid_.pointAt (i);
      if (all_apart_) { // no point joined yet: every candidate lies across
        for (const auto& [begin, end] : grid_.laterCandidates (cell, i))
          for (std::uint32_t j = begin; j < end; ++j)
            visit (a, grid_.pointAt (j));
        continue;
      }
      const std::uint32_t own = component_at_[i];
      for (const auto& [begin, end] : grid_.laterCandidates (cell, i))
        for (std::uint32_t j = begin; j < end;) {
          if (component_at_[j] == own)
            j = run_end_[j];
          else
            visit (a, grid_.pointAt (j++));
        }
    }
  }

private:
  const UniformGrid& grid_;
  bool all_apart_ = true;                   // every point in a component of its own
  std::vector<std::uint32_t> component_at_; // per position: its point's component
  std::vector<std::uint32_t> run_end_; // per position: end of its run in one component
};

/** \brief The minimum spanning forest of the radius graph of \a points: the only
 * edges that H0 of the graph's filtration needs, since the negative edges of the
 * elder rule form that forest (thesis Sec 4.1.4). The edges are the pairs within
 * \a radius that pass \a accept (e.g. a colour and normal test).
 *
 * Kruskal's algorithm. Where a UniformGrid of cell size \a radius has at most
 * SPANNING_FOREST_PAIRS_PER_POINT candidate pairs per point, at that one scale; else
 * copies of a point first (joinCopies()), then scale by scale (spanningForestScales()
 * of the distinct positions, finest first). At each
 * scale s, on a UniformGrid of cell size s, the pairs within s between points not yet
 * joined are listed and added by extendSpanningForest(). A pair within s whose points
 * are joined already would close a cycle of shorter edges, so it is never looked at:
 * at a large radius (an automatic clustering distance searched up to 0.1 m on points
 * 2 mm apart) the search looks at a few pairs per point instead of thousands, and the
 * forest is the same as that of the whole graph, edge for edge.
 *
 * A scale is listed only when it is cheap: its pairs across components are counted
 * first, and the count stops once their edges would not fit \a budget or once
 * SPANNING_FOREST_VISITS_PER_POINT pairs per point were looked at (two large
 * components within a scale of each other: a million pairs across where one edge
 * joins them). From that scale on, extendSpanningForestByBoruvka() finds the rest of
 * the forest, holding one edge per point. So the forest is never refused, whatever
 * the radius: the memory is bounded by \a budget and the points, and the time by the
 * searches, not by the graph's pairs.
 * \param[in] points the points, vertex v at points[v]
 * \param[in] radius the largest edge length (> 0)
 * \param[in] accept the extra symmetric test of a pair (a, b) of vertex ids within the
 * radius, the same for a pair at any scale
 * \param[in] threads OpenMP threads (0: OpenMP's default)
 * \param[in] budget the memory one scale's listed edges may take (bytes_per_edge > 0)
 * \param[out] forest the forest's edges in filtration order
 * \return the most edges listed at one scale
 * \throws pcl::BadArgumentException as UniformGrid */
template <typename Accept>
std::size_t
radiusGraphSpanningForest (const std::vector<Point3d>& points,
                           double radius,
                           const Accept& accept,
                           unsigned int threads,
                           const MemoryBudget& budget,
                           std::vector<FilteredEdge>& forest)
{
  forest.clear();
  UnionFind components (points.size());
  // Where the radius graph is sparse, one scale: its grid is the only one.
  const UniformGrid top (points, radius, threads);
  std::vector<double> scales{radius};
  if (static_cast<double> (top.numCandidatePairs()) >
      SPANNING_FOREST_PAIRS_PER_POINT * static_cast<double> (points.size()))
    scales = spanningForestScales (
        joinCopies (points, accept, components, forest), radius, threads);
  const double max_visits =
      SPANNING_FOREST_VISITS_PER_POINT * static_cast<double> (points.size());
  std::size_t most_listed = 0;
  for (const double scale : scales) {
    const std::optional<UniformGrid> finer =
        scale < radius
            ? std::optional<UniformGrid> (std::in_place, points, scale, threads)
            : std::nullopt;
    const UniformGrid& grid = finer ? *finer : top;
    const ComponentRuns runs (grid, components, points.size());
    const auto joins = [&] (std::uint32_t a, std::uint32_t b) {
      return withinRadius (points[a], points[b], scale) && accept (a, b);
    };
    const auto num_cells = static_cast<std::int64_t> (grid.numCells());
    std::vector<std::uint64_t> offsets (grid.numCells() + 1, 0);
    // The count pass, abandoned soon after it is over the budget or the visits.
    std::atomic<std::uint64_t> counted{0}, visited{0};
    std::atomic<bool> cheap{true};
    const auto report = [&] (std::uint64_t count, std::uint64_t visits) {
      const auto edges = static_cast<double> (counted += count);
      const auto pairs = static_cast<double> (visited += visits);
      if (!budget.fits (edges, 0.0) || pairs > max_visits)
        cheap = false;
    };
#pragma omp parallel for schedule(dynamic, 64) num_threads(resolveThreads(threads))
    for (std::int64_t c = 0; c < num_cells; ++c) {
      std::uint64_t count = 0, visits = 0, reported_count = 0, reported_visits = 0;
      runs.forEachPairAcross (
          c,
          [&] (std::uint32_t a, std::uint32_t b) {
            ++visits;
            count += joins (a, b);
          },
          [&] () { // checked before each point, reported every few thousand pairs
            if (visits - reported_visits >= 4096) {
              report (count - reported_count, visits - reported_visits);
              reported_count = count;
              reported_visits = visits;
            }
            return cheap.load (std::memory_order_relaxed);
          });
      report (count - reported_count, visits - reported_visits);
      offsets[c + 1] = count;
    }
    if (!cheap) {
      extendSpanningForestByBoruvka (
          points, radius, accept, threads, components, forest);
      return std::max (most_listed, points.size());
    }
    most_listed = std::max (most_listed, static_cast<std::size_t> (counted.load()));
    std::partial_sum (offsets.begin(), offsets.end(), offsets.begin());
    auto edges = largeVector<FilteredEdge> (offsets.back());
#pragma omp parallel for schedule(dynamic, 64) num_threads(resolveThreads(threads))
    for (std::int64_t c = 0; c < num_cells; ++c) {
      std::uint64_t position = offsets[c];
      runs.forEachPairAcross (
          c,
          [&] (std::uint32_t a, std::uint32_t b) {
            if (joins (a, b))
              edges[position++] = {
                  std::min (a, b), std::max (a, b), distance (points[a], points[b])};
          },
          [] () { return true; });
    }
    extendSpanningForest (edges, components, forest);
  }
  return most_listed;
}

} // namespace tda
} // namespace pcl
