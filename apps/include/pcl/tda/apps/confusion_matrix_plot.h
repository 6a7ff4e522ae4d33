#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace pcl {
namespace tda {

/** \brief A confusion matrix to draw: counts[t][p] views of true category t
 * classified as p; an extra last column counts views that got no category (their
 * descriptor failed), drawn only when it is not all 0. */
struct ConfusionPlot {
  /** \brief Plain text above the matrix. */
  std::string title;
  std::vector<std::string> categories;
  std::vector<std::vector<std::size_t>> counts;
};

/** \brief Writes \a plot as an SVG picture: one row per true category, one column
 * per predicted category, each cell shaded by its share of the row (white 0, dark
 * blue 1) with the share written in it, the categories named along both sides (the
 * rows with their number of views).
 * \throws pcl::BadArgumentException when counts is not categories x (categories + 1)
 */
void
writeConfusionMatrixSVG (std::ostream& out, const ConfusionPlot& plot);

/** \brief writeConfusionMatrixSVG() to the file \a path, atomically.
 * \throws pcl::IOException when the file cannot be written */
void
saveConfusionMatrixSVG (const std::string& path, const ConfusionPlot& plot);

/** \brief The same picture as a PNG file, atomically, rendered from the SVG by
 * renderSVGToPNG() (librsvg), through a scratch file \a path + ".svg" that is
 * removed after.
 * \throws pcl::IOException when a file cannot be written or the picture rendered */
void
saveConfusionMatrixPNG (const std::string& path, const ConfusionPlot& plot);

} // namespace tda
} // namespace pcl
