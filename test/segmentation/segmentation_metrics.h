#pragma once

// Quality measures of a segmentation against ground truth labels, used by the region
// growing tests and benchmark: the adjusted Rand index over all points (Hubert and
// Arabie 1985) and Hoover's counts of correct, over- and under-segmented regions
// (Hoover et al. 1996).

#include <pcl/PointIndices.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace pcl {
namespace tda {
namespace test {

/** \brief The labels of a segmentation, one per point: the index of its region, or a
 * label of its own (a singleton) for a point in no region. */
inline std::vector<std::int64_t>
segmentLabels (const std::vector<pcl::PointIndices>& regions, std::size_t num_points)
{
  std::vector<std::int64_t> labels (num_points);
  for (std::size_t i = 0; i < num_points; ++i)
    labels[i] = -1 - static_cast<std::int64_t> (i);
  for (std::size_t k = 0; k < regions.size(); ++k)
    for (const auto index : regions[k].indices)
      labels[index] = static_cast<std::int64_t> (k);
  return labels;
}

/** \brief The adjusted Rand index of two labellings of the same points: 1 for equal
 * partitions, about 0 for independent ones. */
inline double
adjustedRandIndex (const std::vector<std::int64_t>& truth,
                   const std::vector<std::int64_t>& found)
{
  const auto pairs = [] (double n) { return n * (n - 1.0) / 2.0; };
  std::map<std::pair<std::int64_t, std::int64_t>, double> joint;
  std::map<std::int64_t, double> rows, columns;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    joint[{truth[i], found[i]}] += 1.0;
    rows[truth[i]] += 1.0;
    columns[found[i]] += 1.0;
  }
  double index = 0.0, row_pairs = 0.0, column_pairs = 0.0;
  for (const auto& [cell, count] : joint)
    index += pairs (count);
  for (const auto& [label, count] : rows)
    row_pairs += pairs (count);
  for (const auto& [label, count] : columns)
    column_pairs += pairs (count);
  const double expected =
      row_pairs * column_pairs / pairs (static_cast<double> (truth.size()));
  const double maximum = 0.5 * (row_pairs + column_pairs);
  return maximum == expected ? 1.0 : (index - expected) / (maximum - expected);
}

/** \brief Hoover's classification of the regions of a segmentation at tolerance T. */
struct HooverCounts {
  /** Ground-truth regions found as one region (mutual overlap >= T of both). */
  std::size_t correct = 0;
  /** Ground-truth regions split into several regions (each >= T inside it, together
   * >= T of it). */
  std::size_t over = 0;
  /** Regions that merge several ground-truth regions (each >= T inside it, together
   * >= T of it). */
  std::size_t under = 0;
  /** Ground-truth regions in none of the above. */
  std::size_t missed = 0;
};

/** \brief Hoover's counts at tolerance \a tolerance (e.g. 0.8) of the labelling
 * \a found (segmentLabels(); singletons are no region) against \a truth. */
inline HooverCounts
hooverCounts (const std::vector<std::int64_t>& truth,
              const std::vector<std::int64_t>& found,
              double tolerance)
{
  std::map<std::pair<std::int64_t, std::int64_t>, double> overlap;
  std::map<std::int64_t, double> truth_size, found_size;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    truth_size[truth[i]] += 1.0;
    if (found[i] < 0)
      continue;
    overlap[{truth[i], found[i]}] += 1.0;
    found_size[found[i]] += 1.0;
  }
  HooverCounts counts;
  std::map<std::int64_t, double> covered_truth, covered_found;
  std::map<std::int64_t, int> parts_of_truth, parts_of_found;
  std::map<std::int64_t, bool> correct;
  for (const auto& [cell, o] : overlap) {
    const auto [g, m] = cell;
    const bool inside_truth = o >= tolerance * found_size[m]; // m lies inside g
    const bool inside_found = o >= tolerance * truth_size[g]; // g lies inside m
    if (inside_truth && inside_found)
      correct[g] = true;
    if (inside_truth) {
      covered_truth[g] += o;
      ++parts_of_truth[g];
    }
    if (inside_found) {
      covered_found[m] += o;
      ++parts_of_found[m];
    }
  }
  std::map<std::int64_t, bool> explained;
  for (const auto& [g, size] : truth_size) {
    if (correct[g])
      ++counts.correct, explained[g] = true;
    else if (parts_of_truth[g] >= 2 && covered_truth[g] >= tolerance * size)
      ++counts.over, explained[g] = true;
  }
  for (const auto& [m, size] : found_size)
    if (parts_of_found[m] >= 2 && covered_found[m] >= tolerance * size) {
      ++counts.under;
      for (const auto& [cell, o] : overlap)
        if (cell.second == m && o >= tolerance * truth_size[cell.first])
          explained[cell.first] = true;
    }
  for (const auto& [g, size] : truth_size)
    counts.missed += !explained[g];
  return counts;
}

} // namespace test
} // namespace tda
} // namespace pcl
