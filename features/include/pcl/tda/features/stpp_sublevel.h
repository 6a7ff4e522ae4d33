#pragma once

// The sublevel-set values of the STPP signature: the components of the sublevel
// sets of a few functions on a coarse copy of the cloud (the H0 of their lower-star
// filtrations, as in the persistent homology transform of Turner, Mukherjee and
// Boyer), which follow the outline and the profile of an object where the
// Vietoris-Rips persistence follows its gaps, components and holes.

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/point3d.h>
#include <pcl/tda/features/signature_types.h>

#include <array>
#include <vector>

namespace pcl {
namespace tda {

/** \brief The functions on \a points whose sublevel sets the STPP signature follows,
 * in units of \a size: the distance from the centroid, and the coordinate along
 * each principal axis (largest variance first) from the centroid, its sign chosen
 * so that its third moment is not negative. They do not change when the cloud is
 * moved or turned, nor, with \a size its size, when it is scaled; given the points
 * in a canonical order, they do not depend on the input order.
 * \return one value per point for each of the STPP_SUBLEVEL_FUNCTIONS functions */
std::array<std::vector<double>, STPP_SUBLEVEL_FUNCTIONS>
shapeFunctions (const std::vector<Point3d>& points, double size);

/** \brief Writes the sublevel-set values of one function into \a values[0,
 * STPP_SUBLEVEL_PER_FUNCTION). \a f holds one value per point of the cloud
 * \a complex was built on (its vertices map to them by pointIndices()). The
 * sublevel complex at t holds the vertices with f <= t and the edges between them
 * (the lower-star filtration of the complex's edges by f). At the STPP_CURVE_SAMPLES
 * values t_j = lo + (j + 1/2) (hi - lo) / STPP_CURVE_SAMPLES, j = 0.., over the
 * range [lo, hi] of f on the vertices:
 * - values[j]: the fraction of the vertices in the sublevel complex (the profile of
 *   the object along f);
 * - values[STPP_CURVE_SAMPLES + j]: log2(1 + c), c the components of the
 *   sublevel complex at t_j that live at least (hi - lo) / STPP_CURVE_SAMPLES (one
 *   step between samples) in the H0 of the filtration (elder rule): the pieces of
 *   the object below t_j, not the specks of a sparse sampling;
 * then values[2 STPP_CURVE_SAMPLES] = hi - lo. */
void
sublevelValues (const FilteredComplex& complex,
                const std::vector<double>& f,
                float* values);

} // namespace tda
} // namespace pcl
