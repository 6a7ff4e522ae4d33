#pragma once

#include <pcl/tda/common/persistence_diagram.h>

#include <cstddef>
#include <limits>
#include <ostream>
#include <string>

namespace pcl {
namespace tda {

/** \brief Rows of essential bars in a barcode are at least this many pixels apart
 * (the bars 2 pixels less high). */
constexpr double MIN_ESSENTIAL_PITCH = 8;

/** \brief How to draw a barcode or a persistence diagram as SVG. */
struct PlotOptions {
  /** \brief Plain text drawn above the picture (escaped for XML); may be empty. */
  std::string title;
  /** \brief At most this many bars per homology dimension in a barcode: the longest
   * are drawn (essential first), the others are counted in a note. At least 1. */
  std::size_t max_bars_per_dimension = 200;
  /** \brief End of the filtration axis, e.g. the filtration radius; 0 takes it from
   * the data (largest finite death or birth). Larger values are drawn at the end. */
  double max_value = 0;
  /** \brief Width of the picture in pixels (at least 300); the height follows. */
  double width = 800;
  /** \brief Unit of the filtration values, e.g. "m": named in the axis titles and
   * after the cut's value; empty (the default) for none. */
  std::string unit;
  /** \brief A filtration value (finite, not negative) marked on a barcode by a
   * vertical dashed line across the panels, labelled "cut" with the value and the
   * unit, e.g. the distance at which clusters were taken; NaN (the default) for
   * none. */
  double cut = std::numeric_limits<double>::quiet_NaN();
};

/** \brief Writes the barcode of \a diagram as an SVG picture (thesis Fig. 4.3 and
 * 6.1): one horizontal bar per interval of non-zero length, one panel per dimension
 * from H0 down, bars sorted by birth, essential classes running to the right end
 * with a red triangle (each at least MIN_ESSENTIAL_PITCH pixels apart, so that
 * several stay visibly separate), an axis in filtration units and, with
 * PlotOptions::cut, the cut line.
 * \throws pcl::BadArgumentException on invalid options, a dimension outside 0..31,
 * a non-finite birth or a death before the birth
 */
void
writeBarcodeSVG (std::ostream& out,
                 const PersistenceDiagram& diagram,
                 const PlotOptions& options = {});

/** \brief Writes the barcode of \a diagram (see writeBarcodeSVG()) to the file
 * \a path, atomically.
 * \throws pcl::IOException when the file cannot be written
 * \throws pcl::BadArgumentException as writeBarcodeSVG()
 */
void
saveBarcodeSVG (const std::string& path,
                const PersistenceDiagram& diagram,
                const PlotOptions& options = {});

/** \brief Writes \a diagram as the classic birth-versus-death scatter plot in SVG:
 * the diagonal, one colour and marker per dimension, essential classes on a dashed
 * "infinity" line at the top. Points closer than a pixel (or a few pixels, so that
 * a dimension needs at most 1000 markers) are merged, the darker the more points a
 * marker stands for, and a note gives the counts.
 * \throws pcl::BadArgumentException as writeBarcodeSVG()
 */
void
writePersistenceDiagramSVG (std::ostream& out,
                            const PersistenceDiagram& diagram,
                            const PlotOptions& options = {});

/** \brief Writes the persistence diagram picture of \a diagram (see
 * writePersistenceDiagramSVG()) to the file \a path, atomically.
 * \throws pcl::IOException when the file cannot be written
 * \throws pcl::BadArgumentException as writeBarcodeSVG()
 */
void
savePersistenceDiagramSVG (const std::string& path,
                           const PersistenceDiagram& diagram,
                           const PlotOptions& options = {});

} // namespace tda
} // namespace pcl
