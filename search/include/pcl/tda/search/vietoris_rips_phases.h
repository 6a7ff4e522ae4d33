#pragma once

#include <pcl/tda/common/progress.h>

#include <cstddef>
#include <utility>

namespace pcl {
namespace tda {

/** \brief Wall-clock seconds of the three phases of the last compute() call of a
 * Vietoris-Rips builder. */
struct VietorisRipsTimings {
  double neighbor_search = 0.0;
  double edges = 0.0;
  double triangles = 0.0;
};

/** \brief The progress of a Vietoris-Rips build in thousandths (done, 1000), as the
 * builders report it: the phases of Ch. 3 end at fixed thousandths, and a phase may
 * report its own work in between. The triangle passes are the long ones when there
 * are triangles. Shared by this module's builder and the gpu/ mirror. */
class VietorisRipsProgress {
public:
  /** The ends of the phases of a build. */
  enum Phase {
    START,
    EDGES_COUNTED,
    EDGES_LISTED,
    EDGES_SORTED,
    TRIANGLES_COUNTED,
    DONE
  };

  /** \param[in] progress the callback (none: reporting costs nothing)
   * \param[in] max_dimension 1 (edges only) or 2 (triangles too) */
  VietorisRipsProgress (ProgressCallback progress, int max_dimension)
  : progress_ (std::move (progress)), with_triangles_ (max_dimension == 2)
  {}

  /** \brief The callback of a phase from \a first to \a last, told the phase's own
   * (done, total); none without a callback. */
  ProgressCallback
  between (Phase first, Phase last) const;

  /** \brief Tells the callback that \a phase is done. */
  void
  reach (Phase phase) const;

private:
  /** Where \a phase ends, in thousandths of the build. */
  std::size_t
  permilleAt (Phase phase) const;

  ProgressCallback progress_;
  bool with_triangles_;
};

} // namespace tda
} // namespace pcl
