#include <pcl/tda/common/edge_adjacency.h>
#include <pcl/tda/features/distance_grid.h>
#include <pcl/tda/features/minimal_cycles.h>
#include <pcl/tda/features/projected_polygon.h>
#include <pcl/tda/features/star_polygon.h>
#include <pcl/tda/search/parallel_progress.h>
#include <pcl/tda/search/radius_edges.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <utility>

namespace pcl {
namespace tda {

namespace {

/** The spanning forest of the negative edges, rooted at the first vertex of each
 * tree, so that the path between two vertices of a tree costs its own length. */
class RootedForest {
public:
  explicit RootedForest (const EdgeAdjacency& forest)
  : parent_ (forest.numVertices(), INVALID_SIMPLEX), depth_ (forest.numVertices(), 0)
  {
    std::vector<std::uint8_t> seen (forest.numVertices(), 0);
    std::vector<SimplexIndex> queue;
    for (SimplexIndex root = 0; root < forest.numVertices(); ++root) {
      if (seen[root])
        continue;
      seen[root] = 1;
      queue.assign (1, root);
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const SimplexIndex v = queue[head];
        for (const auto& entry : forest.neighbors (v))
          if (!seen[entry.neighbor]) {
            seen[entry.neighbor] = 1;
            parent_[entry.neighbor] = v;
            depth_[entry.neighbor] = depth_[v] + 1;
            queue.push_back (entry.neighbor);
          }
      }
    }
  }

  /** The vertices of the tree path from \a u to \a v, both included. */
  std::vector<SimplexIndex>
  path (SimplexIndex u, SimplexIndex v) const
  {
    std::vector<SimplexIndex> from_u, from_v;
    while (depth_[u] > depth_[v]) {
      from_u.push_back (u);
      u = parent_[u];
    }
    while (depth_[v] > depth_[u]) {
      from_v.push_back (v);
      v = parent_[v];
    }
    while (u != v) {
      from_u.push_back (u);
      from_v.push_back (v);
      u = parent_[u];
      v = parent_[v];
    }
    from_u.push_back (u);
    from_u.insert (from_u.end(), from_v.rbegin(), from_v.rend());
    return from_u;
  }

private:
  std::vector<SimplexIndex> parent_;
  std::vector<std::uint32_t> depth_;
};

/** How far, in units of its clearance (plus STAR_POLYGON_MARGIN_EDGES edges), the
 * star polygon around an empty region that a polygon cut through reaches: the
 * region's widest point can lie anywhere in its hole, up to its edge. */
constexpr double REGROW_REACH_PER_CLEARANCE = 1.5;
/** How many times in a row an empty region that a polygon cut through is searched
 * again from a star polygon around it (windingRims()). */
constexpr int MAX_REGROWTHS = 3;

/** Empty regions inside a polygon are searched on a grid of at most this many cells
 * a side over the polygon's box. */
constexpr int EMPTINESS_GRID = 128;

struct EmptyPoint {
  Eigen::Vector2d position;
  double clearance = 0.0;
};

/** The empty regions inside \a polygon: the connected groups of grid cells inside
 * it whose distance to every point of \a points (their clearance) is at least
 * \a min_clearance, each given by its cell of largest clearance. */
std::vector<EmptyPoint>
emptyRegions (const ProjectedPolygon& polygon,
              const std::vector<Eigen::Vector2d>& corners,
              const std::vector<Eigen::Vector2d>& points,
              double min_cell,
              double min_clearance)
{
  Eigen::Vector2d low = corners.front(), high = corners.front();
  for (const Eigen::Vector2d& c : corners) {
    low = low.cwiseMin (c);
    high = high.cwiseMax (c);
  }
  const double cell = std::max ({min_cell,
                                 (high - low).maxCoeff() / EMPTINESS_GRID,
                                 std::numeric_limits<double>::min()});
  const DistanceGrid grid (low, high, cell, points);
  const int nx = grid.width(), ny = grid.height();
  const auto center = [&] (int ix, int iy) { return grid.center (ix, iy); };
  // The cells inside the polygon whose clearance reaches the minimum, grouped
  // into 8-connected regions: one empty region each, found at its widest cell.
  std::vector<double> clearance (static_cast<std::size_t> (nx) * ny, 0.0);
  for (int iy = 0; iy < ny; ++iy) {
    const std::vector<double> xs = polygon.crossings (center (0, iy).y());
    std::size_t left = 0; // crossings left of the cell's centre
    for (int ix = 0; ix < nx; ++ix) {
      while (left < xs.size() && xs[left] <= center (ix, iy).x())
        ++left;
      if ((xs.size() - left) % 2 == 1)
        clearance[static_cast<std::size_t> (iy) * nx + ix] = grid.distance (ix, iy);
    }
  }
  std::vector<EmptyPoint> regions;
  std::vector<std::uint8_t> visited (clearance.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t first = 0; first < clearance.size(); ++first) {
    if (visited[first] || !(clearance[first] >= min_clearance))
      continue;
    std::size_t widest = first;
    visited[first] = 1;
    stack.assign (1, first);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      if (clearance[c] > clearance[widest])
        widest = c;
      const int cx = static_cast<int> (c % nx), cy = static_cast<int> (c / nx);
      for (int y = std::max (0, cy - 1); y <= std::min (ny - 1, cy + 1); ++y)
        for (int x = std::max (0, cx - 1); x <= std::min (nx - 1, cx + 1); ++x) {
          const std::size_t next = static_cast<std::size_t> (y) * nx + x;
          if (!visited[next] && clearance[next] >= min_clearance) {
            visited[next] = 1;
            stack.push_back (next);
          }
        }
    }
    regions.push_back (
        {center (static_cast<int> (widest % nx), static_cast<int> (widest / nx)),
         clearance[widest]});
  }
  return regions;
}

/** Steps 2-4 of Alg 5.15 for one class at a time, with per-vertex scratch reset by
 * marks and the region's graph kept for its storage (one object per thread). */
class RimFinder {
private:
  /** What the searches know of a vertex, together so that a visit reads one cache
   * line. Marks hold the generation_ of the cycle they were made for. */
  struct VertexState {
    Eigen::Vector2d projected;   // in the plane of the polygon
    std::uint32_t in_region = 0; // mark: in the region
    std::uint32_t outside = 0;   // mark: found outside the polygon
    std::uint32_t local = 0;     // number in the region (the cycle's first)
  };

  /** The edges a cycle through a region may take: per vertex of the region (by its
   * index in the region), its neighbours in the region joined to it by an edge of
   * the cycle or a chord, in the order of the adjacency lists, with the edges'
   * lengths. Built once per region, then walked by every search in it; kept
   * between regions for its storage. */
  struct RegionGraph {
    struct Arc {
      std::uint32_t head;
      double length;
    };
    std::vector<std::size_t> offsets;
    std::vector<Arc> arcs;
  };

public:
  /** \param[in] graph the adjacency lists of the complex
   * \param[in] lengths per entry of \a graph, the length of its edge
   * \param[in] positions the position of every vertex
   * \param[in] min_cell the smallest cell of the grids of empty regions
   * \param[in] min_clearance the radius of the smallest empty disk of a hole */
  RimFinder (const EdgeAdjacency& graph,
             const std::vector<double>& lengths,
             const std::vector<Point3d>& positions,
             double min_cell,
             double min_clearance)
  : graph_ (graph)
  , lengths_ (lengths)
  , positions_ (positions)
  , min_cell_ (min_cell)
  , min_clearance_ (min_clearance)
  , longest_edge_ (lengths.empty() ? 0.0
                                   : *std::max_element (lengths.begin(), lengths.end()))
  , vertices_ (positions.size())
  , seen_ (positions.size(), 0)
  {}

  /** The rims around the empty regions inside the polygon of \a cycle, each
   * found again in the plane of its own points (the plane of a long initial cycle
   * on a curved surface can be far from the hole's): a rim whose own polygon holds
   * no empty region wide enough is dropped. */
  std::vector<MinimalCycle>
  rims (const std::vector<SimplexIndex>& cycle, SimplexIndex class_edge)
  {
    std::vector<MinimalCycle> result;
    for (const MinimalCycle& first : windingRims (cycle, class_edge, MAX_REGROWTHS)) {
      std::optional<MinimalCycle> again = foundAgain (first.vertices);
      if (again) {
        again->class_edge = class_edge;
        result.push_back (std::move (*again));
      }
    }
    return result;
  }

private:
  /** The widest rim around the empty regions inside the polygon of \a rim, if any.
   * Many classes go around the same hole and find the same rim first: each rim is
   * searched once (per thread). */
  std::optional<MinimalCycle>
  foundAgain (const std::vector<SimplexIndex>& rim)
  {
    const auto known = found_again_.find (rim);
    if (known != found_again_.end())
      return known->second;
    std::vector<MinimalCycle> again = windingRims (rim, INVALID_SIMPLEX, 0);
    const auto widest = std::max_element (
        again.begin(), again.end(), [] (const MinimalCycle& a, const MinimalCycle& b) {
          return a.clearance < b.clearance;
        });
    std::optional<MinimalCycle> result;
    if (widest != again.end())
      result = std::move (*widest);
    found_again_.emplace (rim, result);
    return result;
  }

  /** The shortest cycles around the empty regions inside the polygon of \a cycle.
   * An empty region that no cycle of the region inside the polygon goes around lies
   * across the polygon: the polygon cuts through its hole (a border polygon built
   * around a centre guessed off the hole's, on a curved or noisy surface). Up to
   * \a regrowths times, such a region is searched again from the star polygon around
   * its widest point that reaches REGROW_REACH_PER_CLEARANCE times its clearance and
   * STAR_POLYGON_MARGIN_EDGES edges beyond (its clearance, measured inside the
   * polygon, grows as the polygon covers more of the hole). */
  std::vector<MinimalCycle>
  windingRims (const std::vector<SimplexIndex>& cycle,
               SimplexIndex class_edge,
               int regrowths)
  {
    const ProjectedPolygon polygon (positions_, cycle);
    ++generation_;
    cycle_length_ = static_cast<std::uint32_t> (cycle.size());
    std::vector<SimplexIndex> region = cycle;
    std::vector<Eigen::Vector2d> corners;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      VertexState& vertex = vertices_[cycle[i]];
      vertex.in_region = generation_;
      vertex.local = static_cast<std::uint32_t> (i);
      vertex.projected = polygon.project (positions_[cycle[i]]);
      corners.push_back (vertex.projected);
    }
    fillRegion (polygon, region);
    std::vector<Eigen::Vector2d> region_points;
    region_points.reserve (region.size());
    for (const SimplexIndex v : region)
      region_points.push_back (vertices_[v].projected);
    std::vector<MinimalCycle> result;
    const std::vector<EmptyPoint> holes =
        emptyRegions (polygon, corners, region_points, min_cell_, min_clearance_);
    if (holes.empty())
      return result;
    keepCycleEdgesAndChords (polygon, region, region_points);
    std::vector<MinimalCycle> open;
    for (const EmptyPoint& hole : holes) {
      MinimalCycle rim;
      rim.class_edge = class_edge;
      rim.vertices = windingCycle (region_graph_, region, region_points, hole.position);
      rim.clearance = hole.clearance;
      const Eigen::Vector3d center = polygon.centroid() +
                                     hole.position.x() * polygon.axisU() +
                                     hole.position.y() * polygon.axisV();
      rim.hole_center = {center.x(), center.y(), center.z()};
      (rim.vertices.size() >= 3 ? result : open).push_back (std::move (rim));
    }
    if (regrowths == 0)
      return result;
    // The region's vertices are kept: the searches below reuse the finder's state.
    for (const MinimalCycle& hole : open) {
      const Eigen::Vector3d centre (
          hole.hole_center[0], hole.hole_center[1], hole.hole_center[2]);
      const double reach = REGROW_REACH_PER_CLEARANCE * hole.clearance +
                           STAR_POLYGON_MARGIN_EDGES * longest_edge_;
      std::vector<SimplexIndex> start;
      for (const SimplexIndex v : region)
        if ((Eigen::Vector3d (positions_[v][0], positions_[v][1], positions_[v][2]) -
             centre)
                .norm() <= reach)
          start.push_back (v);
      const std::vector<SimplexIndex> star = starPolygonAround (
          centre, reach, start, positions_, graph_, longest_edge_, seen_);
      if (star.size() < 3)
        continue;
      for (MinimalCycle& rim : windingRims (star, class_edge, regrowths - 1))
        result.push_back (std::move (rim));
    }
    return result;
  }

  /** Adds to \a region (the cycle, marked) the vertices inside \a polygon that are
   * reached from it through edges without leaving the polygon, numbering them in
   * order, and fills region_graph_ with all edges between them. A vertex found
   * outside is marked, so that it is tested once. */
  void
  fillRegion (const ProjectedPolygon& polygon, std::vector<SimplexIndex>& region)
  {
    region_graph_.offsets.assign (1, 0);
    region_graph_.arcs.clear();
    for (std::size_t head = 0; head < region.size(); ++head) {
      const SimplexIndex v = region[head];
      for (std::size_t k = graph_.offsets[v]; k < graph_.offsets[v + 1]; ++k) {
        const SimplexIndex w = graph_.entries[k].neighbor;
        VertexState& vertex = vertices_[w];
        if (vertex.outside == generation_)
          continue;
        if (vertex.in_region != generation_) {
          const Eigen::Vector2d q = polygon.project (positions_[w]);
          if (!polygon.contains (q)) {
            vertex.outside = generation_;
            continue;
          }
          vertex.in_region = generation_;
          vertex.local = static_cast<std::uint32_t> (region.size());
          vertex.projected = q;
          region.push_back (w);
        }
        region_graph_.arcs.push_back ({vertex.local, lengths_[k]});
      }
      region_graph_.offsets.push_back (region_graph_.arcs.size());
    }
  }

  /** Keeps in region_graph_ the edges of the cycle and the chords of \a polygon,
   * the edges that cycles in it may take. An edge between two vertices after the
   * cycle is tested once, from its first end, for both of its arcs. */
  void
  keepCycleEdgesAndChords (const ProjectedPolygon& polygon,
                           const std::vector<SimplexIndex>& region,
                           const std::vector<Eigen::Vector2d>& points)
  {
    std::vector<std::size_t>& offsets = region_graph_.offsets;
    std::vector<RegionGraph::Arc>& arcs = region_graph_.arcs;
    decided_.assign (arcs.size(), Decision::OPEN);
    std::size_t kept = 0;
    for (std::size_t head = 0, first = 0; head < region.size(); ++head) {
      // The vertices after the cycle are numbered by their place in the region; a
      // vertex twice on the cycle by its last place.
      const std::uint32_t v = head < cycle_length_ ? vertices_[region[head]].local
                                                   : static_cast<std::uint32_t> (head);
      const std::size_t last = offsets[head + 1];
      for (std::size_t arc = first; arc < last; ++arc) {
        const std::uint32_t w = arcs[arc].head;
        bool keep = decided_[arc] == Decision::KEEP;
        if (decided_[arc] == Decision::OPEN) {
          keep = admissible (polygon, points, v, w);
          if (v >= cycle_length_ && w > v)
            decideReverse (w, v, keep);
        }
        if (keep)
          arcs[kept++] = arcs[arc];
      }
      first = last;
      offsets[head + 1] = kept;
    }
    arcs.resize (kept);
  }

  /** Records \a keep for the arc from \a w to \a v, which are after the cycle, with
   * \a w's arcs still as gathered. */
  void
  decideReverse (std::uint32_t w, std::uint32_t v, bool keep)
  {
    const std::vector<RegionGraph::Arc>& arcs = region_graph_.arcs;
    for (std::size_t arc = region_graph_.offsets[w]; arc < region_graph_.offsets[w + 1];
         ++arc)
      if (arcs[arc].head == v) {
        decided_[arc] = keep ? Decision::KEEP : Decision::DROP;
        return;
      }
  }

  /** True when the edge between the region's vertices numbered \a a and \a b (at
   * \a points) is an edge of the cycle or a chord of \a polygon. */
  bool
  admissible (const ProjectedPolygon& polygon,
              const std::vector<Eigen::Vector2d>& points,
              std::uint32_t a,
              std::uint32_t b) const
  {
    // The cycle's vertices are numbered first, in cycle order.
    const std::uint32_t first = std::min (a, b), last = std::max (a, b);
    if (last < cycle_length_ &&
        (first + 1 == last || (first == 0 && last + 1 == cycle_length_)))
      return true; // an edge of the cycle itself (the last closes it)
    return polygon.contains ((points[a] + points[b]) / 2.0);
  }

  /** True when the segment from \a a to \a b crosses the ray from \a p along the
   * first axis of the plane. */
  static bool
  crossesRay (const Eigen::Vector2d& a,
              const Eigen::Vector2d& b,
              const Eigen::Vector2d& p)
  {
    return (a.y() > p.y()) != (b.y() > p.y()) &&
           p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
  }

  /** The shortest closed path through the region that winds around \a p an odd
   * number of times: Dijkstra on two copies of the region's graph (the parity of
   * the crossings of a ray from \a p), from the region's vertex nearest to \a p,
   * s, in copy 0, toward its copy s'. The graph is the same seen from either copy,
   * so the way back from a vertex x to s' is as long as the way from s to x's
   * other copy: the path s -> u -> v -> s' through an edge uv is the path to u, the
   * edge, and the path to v's other copy, reversed. The search meets itself in the
   * middle: it stops once it settles vertices half as far as the shortest such
   * path found, which is then the shortest (the two halves of the shortest path
   * are settled before), having searched a disk of half the radius of a search for
   * s' itself. \a points are the region's vertices in the plane. */
  static std::vector<SimplexIndex>
  windingCycle (const RegionGraph& graph,
                const std::vector<SimplexIndex>& region,
                const std::vector<Eigen::Vector2d>& points,
                const Eigen::Vector2d& p)
  {
    std::size_t start = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
      if ((points[i] - p).squaredNorm() < (points[start] - p).squaredNorm())
        start = i;
    // Ids: the region's vertices, each in two copies (parity 0 and 1).
    const std::size_t n = region.size();
    constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
    const auto other_copy = [n] (std::uint32_t id) {
      return static_cast<std::uint32_t> (id >= n ? id - n : id + n);
    };
    std::vector<double> distance (2 * n, std::numeric_limits<double>::infinity());
    std::vector<std::uint32_t> previous (2 * n, NONE);
    std::vector<std::uint8_t> settled (2 * n, 0);
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    const auto source = static_cast<std::uint32_t> (start);
    distance[source] = 0.0;
    queue.push ({0.0, source});
    double shortest = std::numeric_limits<double>::infinity();
    std::uint32_t last_out = NONE, first_back = NONE; // the middle edge of the best
    while (!queue.empty()) {
      const auto [d, id] = queue.top();
      queue.pop();
      if (d > distance[id])
        continue;
      if (2.0 * d >= shortest)
        break;
      settled[id] = 1;
      const std::uint32_t parity = id >= n ? 1 : 0;
      const std::size_t v = id - parity * n;
      for (std::size_t arc = graph.offsets[v]; arc < graph.offsets[v + 1]; ++arc) {
        const std::uint32_t w = graph.arcs[arc].head;
        const std::uint32_t flip = crossesRay (points[v], points[w], p) ? 1 : 0;
        const auto next = static_cast<std::uint32_t> (w + (parity ^ flip) * n);
        const double through = d + graph.arcs[arc].length;
        const std::uint32_t back = other_copy (next);
        if (settled[back] && through + distance[back] < shortest) {
          shortest = through + distance[back];
          last_out = id;
          first_back = back;
        }
        if (through < distance[next]) {
          distance[next] = through;
          previous[next] = id;
          queue.push ({through, next});
        }
      }
    }
    std::vector<SimplexIndex> cycle;
    if (last_out == NONE)
      return cycle;
    for (std::uint32_t id = last_out; id != NONE; id = previous[id])
      cycle.push_back (region[id >= n ? id - n : id]);
    std::reverse (cycle.begin(), cycle.end()); // s ... u
    for (std::uint32_t id = first_back; id != source; id = previous[id])
      cycle.push_back (region[id >= n ? id - n : id]); // v ... (s)
    return cycle;
  }

  const EdgeAdjacency& graph_;
  const std::vector<double>& lengths_;
  const std::vector<Point3d>& positions_;
  double min_cell_;
  double min_clearance_;
  double longest_edge_;
  std::uint32_t generation_ = 0;
  std::vector<VertexState> vertices_;
  std::vector<std::uint8_t> seen_;
  std::uint32_t cycle_length_ = 0;
  RegionGraph region_graph_;
  /** Per arc of region_graph_, whether keepCycleEdgesAndChords() keeps it. */
  enum class Decision : std::uint8_t { OPEN, KEEP, DROP };
  std::vector<Decision> decided_;
  std::map<std::vector<SimplexIndex>, std::optional<MinimalCycle>> found_again_;
};

/** Initial cycles of at least this many points are compared with each other
 * (nearDuplicates()). */
constexpr std::size_t LONG_CYCLE_POINTS = 1000;
/** The share of their points two long initial cycles must have in common to be
 * nearly the same polygon. */
constexpr double SAME_POLYGON_SHARE = 0.9;

/** The number of elements two sorted vectors have in common (as multisets). */
std::size_t
sharedCount (const std::vector<SimplexIndex>& a, const std::vector<SimplexIndex>& b)
{
  std::size_t shared = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] < b[j])
      ++i;
    else if (b[j] < a[i])
      ++j;
    else {
      ++shared;
      ++i;
      ++j;
    }
  }
  return shared;
}

/** Per initial cycle, 1 when it is long and shares SAME_POLYGON_SHARE of its points,
 * and of the other's, with an earlier long cycle that is searched. Many classes can go
 * around the same large region with nearly the same cycle (about 25 around the
 * table top of table_scene_mug_stereo_textured.pcd with a fifth of its points
 * removed, 3,200-3,800 points each, polygons of 40,000-58,000 points), and each would
 * fill that region and search the same empty regions in it again. */
std::vector<std::uint8_t>
nearDuplicates (const std::vector<InitialCycle>& initial)
{
  std::vector<std::uint8_t> duplicate (initial.size(), 0);
  // The long cycles searched so far, their points sorted, by number of points.
  std::multimap<std::size_t, std::vector<SimplexIndex>> searched;
  for (std::size_t i = 0; i < initial.size(); ++i) {
    const std::size_t size = initial[i].vertices.size();
    if (size < LONG_CYCLE_POINTS)
      continue;
    std::vector<SimplexIndex> points = initial[i].vertices;
    std::sort (points.begin(), points.end());
    // Sharing that many points needs about as many points.
    const auto first = searched.lower_bound (
        static_cast<std::size_t> (std::ceil (SAME_POLYGON_SHARE * size)));
    const auto last =
        searched.upper_bound (static_cast<std::size_t> (size / SAME_POLYGON_SHARE));
    duplicate[i] = std::any_of (first, last, [&] (const auto& other) {
      return sharedCount (points, other.second) >=
             SAME_POLYGON_SHARE * std::max (size, other.first);
    });
    if (!duplicate[i])
      searched.emplace (size, std::move (points));
  }
  return duplicate;
}

} // namespace

std::vector<SimplexIndex>
essentialEdges (const PersistenceResult& result)
{
  std::vector<SimplexIndex> essential;
  for (std::size_t e = 0; e < result.edge_positive.size(); ++e)
    if (result.edge_positive[e] && result.edge_killer[e] == INVALID_SIMPLEX)
      essential.push_back (static_cast<SimplexIndex> (e));
  return essential;
}

std::vector<SimplexIndex>
persistentClassEdges (const std::vector<FilteredEdge>& edges,
                      const std::vector<std::uint8_t>& edge_positive,
                      const std::vector<double>& edge_death,
                      double radius,
                      double persistence_radius)
{
  std::vector<SimplexIndex> persistent;
  for (std::size_t e = 0; e < edges.size() && edges[e].value <= radius; ++e)
    if (edge_positive[e] && edge_death[e] > persistence_radius)
      persistent.push_back (static_cast<SimplexIndex> (e));
  return persistent;
}

std::vector<InitialCycle>
classCycles (const FilteredComplex& complex,
             const std::vector<std::uint8_t>& edge_positive,
             const std::vector<SimplexIndex>& class_edges)
{
  const auto& edges = complex.edges();
  const RootedForest forest (
      buildEdgeAdjacency (complex.numVertices(), edges, [&] (SimplexIndex e) {
        return !edge_positive[e];
      }));
  std::vector<InitialCycle> cycles;
  cycles.reserve (class_edges.size());
  for (const SimplexIndex e : class_edges)
    cycles.push_back ({forest.path (edges[e].source, edges[e].target), e});
  return cycles;
}

std::vector<MinimalCycle>
minimalCycles (const FilteredComplex& complex,
               const std::vector<InitialCycle>& initial,
               const std::vector<Point3d>& positions,
               const EdgeAdjacency& adjacency,
               double min_clearance,
               unsigned int threads,
               const ProgressCallback& progress)
{
  std::vector<std::vector<MinimalCycle>> per_class (initial.size());
  const auto& edges = complex.edges();
  const auto count = static_cast<std::int64_t> (initial.size());
  // The searches read the edges' lengths along the adjacency lists, not at random.
  std::vector<double> lengths (adjacency.entries.size());
  for (std::size_t k = 0; k < lengths.size(); ++k)
    lengths[k] = edges[adjacency.entries[k].edge].value;
  const std::vector<std::uint8_t> duplicate = nearDuplicates (initial);
  // A callback that throws cannot leave the parallel loop: the tracker keeps it.
  ParallelProgress tracker (progress, initial.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    // Cells of a quarter of the smallest clearance sought: fine enough to tell it.
    RimFinder finder (
        adjacency, lengths, positions, min_clearance / 4.0, min_clearance);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < count; ++i) {
      if (!duplicate[i])
        per_class[i] = finder.rims (initial[i].vertices, initial[i].class_edge);
      tracker.advance (1);
    }
  }
  tracker.rethrow();
  std::vector<MinimalCycle> cycles;
  for (auto& rims : per_class)
    for (MinimalCycle& rim : rims)
      cycles.push_back (std::move (rim));
  return cycles;
}

} // namespace tda
} // namespace pcl
