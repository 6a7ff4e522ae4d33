#include <pcl/common/eigen.h>
#include <pcl/tda/common/plane_fit.h>
#include <pcl/tda/search/nearest_neighbors.h>
#include <pcl/tda/segmentation/homogeneity_graph.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace pcl {
namespace tda {
namespace {

/** How many times the typical change (the noise) a colour may change at most. */
constexpr float NOISE_CHANGES = 3.0f;
/** The typical change is measured on every this many-th vertex. */
constexpr std::size_t NOISE_SAMPLE_STRIDE = 8;

/** The key of the edge between \a a and \a b, for a sorted set of edges. */
std::uint64_t
edgeKey (SimplexIndex a, SimplexIndex b)
{
  return (static_cast<std::uint64_t> (std::min (a, b)) << 32) | std::max (a, b);
}

/** Appends to \a graph the edges of \a added that it does not have, once each;
 * the edges within \a radius are in it already (the radius graph). */
void
appendNewEdges (double radius,
                std::vector<FilteredEdge> added,
                std::vector<FilteredEdge>& graph)
{
  std::vector<std::uint64_t> longer;
  for (const FilteredEdge& edge : graph)
    if (edge.value > radius)
      longer.push_back (edgeKey (edge.source, edge.target));
  std::sort (longer.begin(), longer.end());
  std::sort (added.begin(), added.end(), edgeFiltrationLess);
  std::uint64_t previous = std::numeric_limits<std::uint64_t>::max();
  for (const FilteredEdge& edge : added) {
    const std::uint64_t key = edgeKey (edge.source, edge.target);
    if (key != previous && !std::binary_search (longer.begin(), longer.end(), key))
      graph.push_back (edge);
    previous = key;
  }
}

/** Sorts the pair (\a x, \a y) of colours channel by channel, without a branch. */
void
sortChannels (LabColor& x, LabColor& y)
{
  for (float LabColor::*channel : {&LabColor::l, &LabColor::a, &LabColor::b}) {
    const float low = std::min (x.*channel, y.*channel);
    y.*channel = std::max (x.*channel, y.*channel);
    x.*channel = low;
  }
}

/** The compare-exchanges of Batcher's odd-even merge sort of \a slots (a power of 2,
 * at most 256) values, in order. */
std::vector<std::pair<std::uint8_t, std::uint8_t>>
oddEvenMergeSort (std::size_t slots)
{
  std::vector<std::pair<std::uint8_t, std::uint8_t>> network;
  for (std::size_t p = 1; p < slots; p *= 2)
    for (std::size_t k = p; k >= 1; k /= 2)
      for (std::size_t j = k % p; j + k < slots; j += 2 * k)
        for (std::size_t i = 0; i < k && i + j + k < slots; ++i)
          if ((i + j) / (2 * p) == (i + j + k) / (2 * p))
            network.emplace_back (i + j, i + j + k);
  return network;
}

/** The median of each channel of \a values (the upper middle value of an even count),
 * which it reorders. Up to 32 colours are sorted channel by channel by Batcher's
 * odd-even merge sort on 16 or 32 slots padded with infinity: the same fixed
 * compare-exchanges for every vertex, branch-free, which on the dozen colours of a
 * neighbourhood is several times faster than a selection per channel. */
LabColor
channelMedians (std::vector<LabColor>& values)
{
  const std::size_t count = values.size(), middle = count / 2;
  if (count > 32) {
    LabColor median;
    std::vector<float> channel_values (count);
    for (float LabColor::*channel : {&LabColor::l, &LabColor::a, &LabColor::b}) {
      std::transform (values.begin(),
                      values.end(),
                      channel_values.begin(),
                      [channel] (const LabColor& x) { return x.*channel; });
      std::nth_element (channel_values.begin(),
                        channel_values.begin() + middle,
                        channel_values.end());
      median.*channel = channel_values[middle];
    }
    return median;
  }
  static const std::vector<std::pair<std::uint8_t, std::uint8_t>> network16 =
      oddEvenMergeSort (16);
  static const std::vector<std::pair<std::uint8_t, std::uint8_t>> network32 =
      oddEvenMergeSort (32);
  const auto& network = count > 16 ? network32 : network16;
  constexpr float inf = std::numeric_limits<float>::infinity();
  values.resize (count > 16 ? 32 : 16, LabColor{inf, inf, inf});
  for (const auto& [first, second] : network)
    sortChannels (values[first], values[second]);
  return values[middle];
}

} // namespace

bool
neighborGraph (const std::vector<Point3d>& points,
               double radius,
               unsigned int threads,
               const MemoryBudget& budget,
               std::vector<FilteredEdge>& edges,
               ComplexSize& size,
               const ProgressCallback& progress)
{
  edges.clear();
  const UniformGrid grid (points, radius, threads);
  // The count and the fill pass are each half of the work.
  const auto half = [&progress] (std::size_t pass) -> ProgressCallback {
    if (!progress)
      return {};
    return [&progress, pass] (std::size_t done, std::size_t total) {
      progress (pass * total + done, 2 * total);
    };
  };
  RadiusEdgeCounts counts;
  if (!countRadiusEdgesWithinBudget (grid,
                                     points,
                                     radius,
                                     AcceptAllPairs{},
                                     threads,
                                     budget,
                                     counts,
                                     size,
                                     half (0)))
    return false;
  edges = listRadiusEdges (
      grid, points, radius, AcceptAllPairs{}, counts.offsets, threads, half (1));
  return true;
}

void
addNearestNeighbors (const std::vector<Point3d>& points,
                     double radius,
                     std::size_t k,
                     unsigned int threads,
                     std::vector<FilteredEdge>& graph)
{
  if (k == 0 || points.size() < 2)
    return;
  std::vector<std::size_t> degree (points.size(), 0);
  for (const FilteredEdge& edge : graph) {
    ++degree[edge.source];
    ++degree[edge.target];
  }
  if (std::none_of (
          degree.begin(), degree.end(), [k] (std::size_t d) { return d < k; }))
    return;
  std::vector<std::uint32_t> sparse; // the vertices of degree below k
  for (SimplexIndex v = 0; v < points.size(); ++v)
    if (degree[v] < k)
      sparse.push_back (v);
  // Several times k: along a dense row of points the k nearest are all in the row.
  const std::size_t wanted = std::min (3 * k + 1, points.size());
  std::vector<std::uint32_t> neighbors;
  std::vector<float> squared_distances;
  NearestNeighbors (floatCoordinates (points))
      .search (floatCoordinates (points, sparse),
               wanted,
               threads,
               neighbors,
               squared_distances);
  std::vector<FilteredEdge> added;
  for (std::size_t q = 0; q < sparse.size(); ++q) {
    const SimplexIndex v = sparse[q];
    for (std::size_t j = q * wanted; j < (q + 1) * wanted; ++j) {
      const SimplexIndex w = neighbors[j];
      if (w == v || withinRadius (points[v], points[w], radius))
        continue; // itself, or already an edge of the radius graph
      added.push_back (
          {std::min (v, w), std::max (v, w), distance (points[v], points[w])});
    }
  }
  appendNewEdges (radius, std::move (added), graph);
}

void
addImageNeighbors (const std::vector<Point3d>& points,
                   const std::vector<SimplexIndex>& vertex_of_pixel,
                   std::size_t width,
                   const Point3d& sensor,
                   double radius,
                   double range_ratio,
                   std::vector<FilteredEdge>& graph)
{
  if (range_ratio <= 0.0 || width == 0)
    return;
  const std::size_t height = vertex_of_pixel.size() / width;
  std::vector<FilteredEdge> added;
  // Every pair of neighbouring pixels once: right, and the three below.
  const int steps[4][2] = {{0, 1}, {1, -1}, {1, 0}, {1, 1}};
  for (std::size_t row = 0; row < height; ++row)
    for (std::size_t column = 0; column < width; ++column) {
      const SimplexIndex v = vertex_of_pixel[row * width + column];
      if (v == INVALID_SIMPLEX)
        continue;
      for (const auto& step : steps) {
        const std::size_t next_row = row + step[0];
        const auto next_column = static_cast<std::ptrdiff_t> (column) + step[1];
        if (next_row >= height || next_column < 0 ||
            next_column >= static_cast<std::ptrdiff_t> (width))
          continue;
        const SimplexIndex w = vertex_of_pixel[next_row * width + next_column];
        if (w == INVALID_SIMPLEX || w == v ||
            withinRadius (points[v], points[w], radius))
          continue;
        const double length = distance (points[v], points[w]);
        const double range =
            std::min (distance (points[v], sensor), distance (points[w], sensor));
        if (length <= range_ratio * range)
          added.push_back ({std::min (v, w), std::max (v, w), length});
      }
    }
  appendNewEdges (radius, std::move (added), graph);
}

NeighborLists
neighborLists (std::size_t num_vertices, const std::vector<FilteredEdge>& graph)
{
  NeighborLists lists;
  lists.offsets.assign (num_vertices + 1, 0);
  for (const FilteredEdge& edge : graph) {
    ++lists.offsets[edge.source + 1];
    ++lists.offsets[edge.target + 1];
  }
  std::partial_sum (lists.offsets.begin(), lists.offsets.end(), lists.offsets.begin());
  lists.neighbors.resize (lists.offsets.back());
  std::vector<std::size_t> next (lists.offsets.begin(), lists.offsets.end() - 1);
  for (const FilteredEdge& edge : graph) {
    lists.neighbors[next[edge.source]++] = edge.target;
    lists.neighbors[next[edge.target]++] = edge.source;
  }
  return lists;
}

std::vector<Eigen::Vector3f>
neighborNormals (const std::vector<Point3d>& points,
                 const NeighborLists& lists,
                 unsigned int threads)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Eigen::Vector3f> normals (points.size(), Eigen::Vector3f (nan, nan, nan));
  const auto num_vertices = static_cast<std::int64_t> (points.size());
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolveThreads(threads))
  for (std::int64_t v = 0; v < num_vertices; ++v) {
    const std::size_t begin = lists.offsets[v], end = lists.offsets[v + 1];
    if (end - begin < 2)
      continue;
    // The vertex and its neighbours, offsets taken from the vertex.
    const Point3d& origin = points[v];
    PlaneFit plane (origin);
    plane.add (origin);
    for (std::size_t k = begin; k < end; ++k)
      plane.add (points[lists.neighbors[k]]);
    Eigen::Vector3f normal = plane.normal();
    const Eigen::Vector3f position (static_cast<float> (origin[0]),
                                    static_cast<float> (origin[1]),
                                    static_cast<float> (origin[2]));
    if (normal.dot (-position) < 0.0f) // towards the viewpoint at the origin
      normal = -normal;
    normals[v] = normal;
  }
  return normals;
}

std::vector<LabColor>
medianSmoothedColors (const std::vector<LabColor>& colors,
                      const NeighborLists& lists,
                      float max_change,
                      unsigned int threads)
{
  // The noise: the median change of a colour by the median of its whole
  // neighbourhood, over a sample of the vertices; a colour changes by up to a few
  // times it.
  std::vector<LabColor> neighborhood;
  std::vector<float> changes;
  for (std::size_t v = 0; v < colors.size(); v += NOISE_SAMPLE_STRIDE) {
    neighborhood.assign (1, colors[v]);
    for (std::size_t k = lists.offsets[v]; k < lists.offsets[v + 1]; ++k)
      neighborhood.push_back (colors[lists.neighbors[k]]);
    changes.push_back (deltaE76 (channelMedians (neighborhood), colors[v]));
  }
  std::nth_element (
      changes.begin(), changes.begin() + changes.size() / 2, changes.end());
  const float limit =
      changes.empty()
          ? max_change
          : std::max (max_change, NOISE_CHANGES * changes[changes.size() / 2]);

  // Neighbours farther than that lie across a border: left out, so that no blend
  // of the two sides forms along it.
  std::vector<LabColor> smoothed (colors.size());
  const auto num_vertices = static_cast<std::int64_t> (colors.size());
#pragma omp parallel num_threads(resolveThreads(threads))
  {
    std::vector<LabColor> values;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t v = 0; v < num_vertices; ++v) {
      values.assign (1, colors[v]);
      for (std::size_t k = lists.offsets[v]; k < lists.offsets[v + 1]; ++k) {
        const LabColor& color = colors[lists.neighbors[k]];
        if (deltaE76 (color, colors[v]) <= limit)
          values.push_back (color);
      }
      const LabColor median = channelMedians (values);
      smoothed[v] = deltaE76 (median, colors[v]) <= limit ? median : colors[v];
    }
  }
  return smoothed;
}

void
valueByHomogeneity (std::vector<FilteredEdge>& graph,
                    const std::vector<LabColor>& colors,
                    const std::vector<Eigen::Vector3f>& normals,
                    double min_cos_angle,
                    unsigned int threads)
{
  const bool with_normals = !normals.empty();
  const auto num_edges = static_cast<std::int64_t> (graph.size());
#pragma omp parallel for schedule(static) num_threads(resolveThreads(threads))
  for (std::int64_t e = 0; e < num_edges; ++e) {
    FilteredEdge& edge = graph[e];
    // A NaN normal fails no test: the comparison is false.
    const bool similar_normals =
        !with_normals ||
        !(std::abs (normals[edge.source].dot (normals[edge.target])) < min_cos_angle);
    edge.value = similar_normals ? deltaE76 (colors[edge.source], colors[edge.target])
                                 : std::numeric_limits<double>::infinity();
  }
}

} // namespace tda
} // namespace pcl
