#include <pcl/tda/common/h0_persistence.h>
#include <pcl/tda/common/persistence_engines.h>
#include <pcl/tda/features/stpp_levels.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_map>
#include <utility>

namespace pcl {
namespace tda {
namespace {

/** \brief The sample radii t_j = from + j (r - from) / STPP_CURVE_SAMPLES, j = 1..,
 * of a level's curves. */
double
curveSample (double from, double radius, std::size_t j)
{
  return from + (radius - from) * static_cast<double> (j + 1) /
                    static_cast<double> (STPP_CURVE_SAMPLES);
}

float
logCount (std::size_t count)
{
  return static_cast<float> (std::log2 (1.0 + static_cast<double> (count)));
}

/** \brief Counts the interval [birth, death) at every curve sample it covers. */
void
addInterval (double birth,
             double death,
             double curve_start,
             double radius,
             std::vector<long>& alive)
{
  for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j) {
    const double t = curveSample (curve_start, radius, j);
    if (birth <= t && t < death)
      ++alive[j];
  }
}

} // namespace

std::vector<std::int64_t>
pairingVector (const FilteredComplex& complex,
               const PersistenceResult& result,
               STPPHomology homology)
{
  std::vector<std::int64_t> pairing;
  const auto entry = [] (SimplexIndex killer) {
    return killer == INVALID_SIMPLEX ? STPP_UNPAIRED
                                     : static_cast<std::int64_t> (killer);
  };
  if (homology != STPPHomology::BETTI_1)
    for (const SimplexIndex killer : result.vertex_killer)
      pairing.push_back (entry (killer));
  if (homology != STPPHomology::BETTI_0)
    for (std::size_t e = 0; e < complex.numEdges(); ++e)
      pairing.push_back (result.edge_positive[e] ? entry (result.edge_killer[e])
                                                 : STPP_NEGATIVE);
  return pairing;
}

double
cloudSize (const std::vector<Point3d>& points)
{
  if (points.empty())
    return 0.0;
  Point3d centroid{0.0, 0.0, 0.0};
  for (const Point3d& p : points)
    for (int axis = 0; axis < 3; ++axis)
      centroid[axis] += p[axis];
  for (double& coordinate : centroid)
    coordinate /= static_cast<double> (points.size());
  double squares = 0.0;
  for (const Point3d& p : points) {
    const double d = distance (p, centroid);
    squares += d * d;
  }
  return 2.0 * std::sqrt (squares / static_cast<double> (points.size()));
}

std::vector<std::size_t>
hashedSample (std::size_t size, std::size_t count)
{
  std::vector<std::size_t> chosen (size);
  for (std::size_t i = 0; i < size; ++i)
    chosen[i] = i;
  if (size <= count)
    return chosen;
  // SplitMix64's finalizer on the position.
  const auto mix = [] (std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  };
  std::nth_element (chosen.begin(),
                    chosen.begin() + static_cast<std::ptrdiff_t> (count),
                    chosen.end(),
                    [&mix] (std::size_t a, std::size_t b) {
                      return std::make_pair (mix (a), a) < std::make_pair (mix (b), b);
                    });
  chosen.resize (count);
  std::sort (chosen.begin(), chosen.end());
  return chosen;
}

std::vector<Point3d>
coarseCopy (const std::vector<Point3d>& points, double spacing)
{
  // Kept points by grid cell of size spacing: a point closer than that to a kept
  // one is in the same or an adjacent cell.
  using Cell = std::array<long, 3>;
  const auto cellOf = [spacing] (const Point3d& p) {
    return Cell{static_cast<long> (std::floor (p[0] / spacing)),
                static_cast<long> (std::floor (p[1] / spacing)),
                static_cast<long> (std::floor (p[2] / spacing))};
  };
  const auto hash = [] (const Cell& c) {
    return std::hash<long>() (c[0] * 73856093L ^ c[1] * 19349663L ^ c[2] * 83492791L);
  };
  // The first kept point of each cell, and the next kept point in its cell.
  std::unordered_map<Cell, std::size_t, decltype (hash)> first_in_cell (
      points.size() / 4 + 1, hash);
  std::vector<std::size_t> next_in_cell;
  constexpr std::size_t NONE = std::numeric_limits<std::size_t>::max();
  std::vector<Point3d> kept;
  for (const Point3d& p : points) {
    const Cell cell = cellOf (p);
    bool covered = false;
    for (long dx = -1; dx <= 1 && !covered; ++dx)
      for (long dy = -1; dy <= 1 && !covered; ++dy)
        for (long dz = -1; dz <= 1 && !covered; ++dz) {
          const auto found =
              first_in_cell.find ({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (found == first_in_cell.end())
            continue;
          for (std::size_t k = found->second; k != NONE && !covered;
               k = next_in_cell[k])
            covered = distance (kept[k], p) < spacing;
        }
    if (!covered) {
      const auto inserted = first_in_cell.emplace (cell, kept.size());
      next_in_cell.push_back (inserted.second ? NONE : inserted.first->second);
      if (!inserted.second)
        inserted.first->second = kept.size();
      kept.push_back (p);
    }
  }
  return kept;
}

void
betti0LevelValues (const FilteredComplex& complex,
                   const PersistenceResult& result,
                   double curve_start,
                   double radius,
                   float* values)
{
  const std::vector<FilteredEdge>& edges = complex.edges();
  std::vector<long> alive (STPP_CURVE_SAMPLES, 0);
  std::size_t components = 0;
  for (const SimplexIndex killer : result.vertex_killer) {
    const double death = killer == INVALID_SIMPLEX
                             ? std::numeric_limits<double>::infinity()
                             : edges[killer].value;
    addInterval (0.0, death, curve_start, radius, alive);
    components += killer == INVALID_SIMPLEX ? 1 : 0;
  }
  const auto n = static_cast<double> (std::max<std::size_t> (1, complex.numVertices()));
  for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j)
    values[j] = static_cast<float> (static_cast<double> (alive[j]) / n);
  values[STPP_CURVE_SAMPLES] = logCount (components);
}

void
betti1LevelValues (const FilteredComplex& complex,
                   const PersistenceResult& result,
                   double curve_start,
                   double radius,
                   float* values)
{
  const std::vector<FilteredEdge>& edges = complex.edges();
  const std::vector<FilteredTriangle>& triangles = complex.triangles();
  std::vector<long> alive (STPP_CURVE_SAMPLES, 0);
  std::size_t essential = 0, long_lived = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!result.edge_positive[e])
      continue;
    const SimplexIndex killer = result.edge_killer[e];
    const double birth = edges[e].value;
    const double death = killer == INVALID_SIMPLEX
                             ? std::numeric_limits<double>::infinity()
                             : triangles[killer].value;
    addInterval (birth, death, curve_start, radius, alive);
    essential += killer == INVALID_SIMPLEX ? 1 : 0;
    long_lived += std::min (death, radius) - birth >= 0.5 * radius ? 1 : 0;
  }
  const auto n = static_cast<double> (std::max<std::size_t> (1, complex.numVertices()));
  for (std::size_t j = 0; j < STPP_CURVE_SAMPLES; ++j)
    values[j] = static_cast<float> (static_cast<double> (alive[j]) / n);
  values[STPP_CURVE_SAMPLES] = logCount (essential);
  values[STPP_CURVE_SAMPLES + 1] = logCount (long_lived);
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
toPointCloud (const std::vector<Point3d>& points)
{
  const auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve (points.size());
  for (const Point3d& p : points)
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p[0]),
                                     static_cast<float> (p[1]),
                                     static_cast<float> (p[2])));
  return cloud;
}

bool
levelPersistence (const std::vector<Point3d>& points,
                  double radius,
                  STPPHomology homology,
                  std::size_t memory_limit,
                  unsigned int threads,
                  FilteredComplex& complex,
                  PersistenceResult& result)
{
  VietorisRipsBuilder<pcl::PointXYZ> builder;
  builder.setInputCloud (toPointCloud (points));
  builder.setRadius (radius);
  builder.setMaxDimension (homology == STPPHomology::BETTI_0 ? 1 : 2);
  builder.setMemoryLimit (memory_limit);
  builder.setNumberOfThreads (threads);
  if (!builder.compute (complex))
    return false;
  result = homology == STPPHomology::BETTI_0 ? computeH0Persistence (complex)
                                             : computePersistence (complex);
  return true;
}

std::vector<float>
stppSignatureValues (const STPPSignature& signature, STPPHomology homology)
{
  const float* begin = signature.histogram;
  std::vector<float> values;
  if (homology != STPPHomology::BETTI_1)
    values.insert (
        values.end(), begin + STPP_BETTI0_OFFSET, begin + STPP_BETTI1_OFFSET);
  if (homology != STPPHomology::BETTI_0)
    values.insert (values.end(), begin + STPP_BETTI1_OFFSET, begin + STPP_SIZE_OFFSET);
  values.push_back (signature.histogram[STPP_SIZE_OFFSET]);
  return values;
}

} // namespace tda
} // namespace pcl
