#include <pcl/tda/generators/random_sampling.h>

#include <utility>

namespace pcl {
namespace tda {

std::vector<std::size_t>
apportion (const std::vector<double>& weights, std::size_t total)
{
  double sum = 0.0;
  for (const double w : weights)
    sum += w;
  std::vector<std::size_t> counts (weights.size());
  std::vector<std::pair<double, std::size_t>> remainders (weights.size());
  std::size_t assigned = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double exact = static_cast<double> (total) * weights[i] / sum;
    counts[i] = static_cast<std::size_t> (std::floor (exact));
    assigned += counts[i];
    remainders[i] = {exact - static_cast<double> (counts[i]), i};
  }
  std::stable_sort (remainders.begin(),
                    remainders.end(),
                    [] (const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; assigned < total; ++i, ++assigned)
    ++counts[remainders[i % remainders.size()].second];
  return counts;
}

std::size_t
cellCount (double length, double spacing)
{
  return std::max<std::size_t> (
      1, static_cast<std::size_t> (std::ceil (length / spacing)));
}

std::vector<SurfaceSample>
sampleSphere (double radius, std::size_t count, PortableRandom& random)
{
  const std::size_t rows = std::max<std::size_t> (
      1, static_cast<std::size_t> (std::lround (std::sqrt (M_PI * count / 4.0))));
  std::vector<double> weights (rows);
  for (std::size_t j = 0; j < rows; ++j)
    weights[j] = std::cos (M_PI * j / rows) - std::cos (M_PI * (j + 1) / rows);
  const std::vector<std::size_t> per_row = apportion (weights, count);
  std::vector<SurfaceSample> samples;
  samples.reserve (count);
  for (std::size_t j = 0; j < rows; ++j) {
    const double z_top = std::cos (M_PI * j / rows);
    const double z_bottom = std::cos (M_PI * (j + 1) / rows);
    for (std::size_t k = 0; k < per_row[j]; ++k) {
      const double z = random.uniform (z_bottom, z_top); // area-uniform in the ring
      const double theta = 2.0 * M_PI * (k + random.uniform()) / per_row[j];
      const double rho = std::sqrt (std::max (0.0, 1.0 - z * z));
      const Eigen::Vector3d n (rho * std::cos (theta), rho * std::sin (theta), z);
      samples.push_back ({radius * n, n});
    }
  }
  return samples;
}

std::vector<SurfaceSample>
sampleTorus (double major_radius,
             double minor_radius,
             std::size_t count,
             PortableRandom& random)
{
  const double big = major_radius, small = minor_radius;
  const double h = std::sqrt (4.0 * M_PI * M_PI * big * small / count);
  // Rings of equal width around the tube, points in proportion to ring area.
  const std::size_t rows = std::max<std::size_t> (
      3, static_cast<std::size_t> (std::lround (2.0 * M_PI * small / h)));
  std::vector<double> weights (rows);
  for (std::size_t j = 0; j < rows; ++j) {
    const double phi0 = 2.0 * M_PI * j / rows;
    const double phi1 = 2.0 * M_PI * (j + 1) / rows;
    weights[j] = big * (phi1 - phi0) + small * (std::sin (phi1) - std::sin (phi0));
  }
  const std::vector<std::size_t> per_row = apportion (weights, count);
  std::vector<SurfaceSample> samples;
  samples.reserve (count);
  for (std::size_t j = 0; j < rows; ++j)
    for (std::size_t k = 0; k < per_row[j]; ++k) {
      const double phi = 2.0 * M_PI * (j + random.uniform()) / rows;
      const double theta = 2.0 * M_PI * (k + random.uniform()) / per_row[j];
      const double rho = big + small * std::cos (phi);
      const Eigen::Vector3d normal (std::cos (phi) * std::cos (theta),
                                    std::cos (phi) * std::sin (theta),
                                    std::sin (phi));
      samples.push_back ({Eigen::Vector3d (rho * std::cos (theta),
                                           rho * std::sin (theta),
                                           small * std::sin (phi)),
                          normal});
    }
  return samples;
}

std::vector<SurfaceSample>
sampleDisc (double radius, double spacing, PortableRandom& random)
{
  const std::size_t rings = cellCount (radius, spacing);
  std::vector<SurfaceSample> samples;
  for (std::size_t j = 0; j < rings; ++j) {
    const double inner = radius * j / rings;
    const double outer = radius * (j + 1) / rings;
    const std::size_t cells =
        cellCount (M_PI * (outer * outer - inner * inner), spacing * spacing);
    for (std::size_t k = 0; k < cells; ++k) {
      const double rho = std::sqrt (random.uniform (inner * inner, outer * outer));
      const double theta = 2.0 * M_PI * (k + random.uniform()) / cells;
      samples.push_back (
          {Eigen::Vector3d (rho * std::cos (theta), rho * std::sin (theta), 0.0),
           Eigen::Vector3d::UnitZ()});
    }
  }
  return samples;
}

void
sampleRectangle (const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& u,
                 const Eigen::Vector3d& v,
                 const Eigen::Vector3d& normal,
                 double spacing,
                 PortableRandom& random,
                 std::vector<SurfaceSample>& samples)
{
  const std::size_t nu = cellCount (u.norm(), spacing);
  const std::size_t nv = cellCount (v.norm(), spacing);
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double s = (i + random.uniform()) / nu;
      const double t = (j + random.uniform()) / nv;
      samples.push_back ({origin + s * u + t * v, normal});
    }
}

} // namespace tda
} // namespace pcl
