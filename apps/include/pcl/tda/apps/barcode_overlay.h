#pragma once

#include <pcl/tda/common/persistence_diagram.h>

#include <array>
#include <cstddef>

// VTK's types by name only, so that code that needs the colours below (the tests)
// does not need VTK's headers.
class vtkPoints;
class vtkRenderer;

namespace pcl {
namespace tda {

/** \brief The H0 and H1 barcode of the viewer's -barcode mode, drawn with VTK 2D
 * actors over the whole of a renderer (its own viewport beside the cloud): a panel
 * per dimension, H0 above, the longest bars of each (essential first), sorted by
 * birth, and a vertical line at the radius shown (thesis Fig 6.1). */
class BarcodeOverlay {
public:
  /** \brief At most this many bars per dimension are drawn. */
  static constexpr std::size_t MAX_BARS = 60;
  /** \brief The colour of the H0 bars. */
  static constexpr std::array<unsigned char, 3> H0_COLOR{90, 160, 255};
  /** \brief The colour of the H1 bars. */
  static constexpr std::array<unsigned char, 3> H1_COLOR{255, 200, 40};

  /** \brief Adds the bars of \a diagram, over the filtration values 0 to
   * \a max_value (bars beyond it are cut there), to \a renderer. */
  BarcodeOverlay (vtkRenderer* renderer,
                  const PersistenceDiagram& diagram,
                  double max_value);

  /** \brief Moves the radius line to \a radius. */
  void
  setRadius (double radius);

private:
  /** The horizontal position of filtration value \a value, in normalized viewport
   * coordinates. */
  double
  position (double value) const;

  double max_value_;
  /** The two ends of the radius line; the renderer's actors keep them. */
  vtkPoints* cursor_;
};

} // namespace tda
} // namespace pcl
