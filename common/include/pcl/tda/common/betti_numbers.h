#pragma once

#include <pcl/tda/common/filtered_complex.h>
#include <pcl/tda/common/persistence_result.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl {
namespace tda {

/** \brief Betti numbers beta_0, beta_1, beta_2 of a complex. */
using BettiNumbers = std::array<std::int64_t, 3>;

/** \brief Betti numbers of every prefix of the global filtration (thesis Alg 5.8):
 * entry i holds those of the subcomplex made of the first i + 1 simplices of
 * FilteredComplex::filtrationOrder(). A positive k-simplex adds one to beta_k, a
 * negative one takes one from beta_(k-1) (Eq. 5.1).
 * \param[in] complex the filtered complex
 * \param[in] result the positive/negative marks of an engine that computed all
 * dimensions of \a complex
 * \throws pcl::BadArgumentException when \a result lacks marks for \a complex
 */
std::vector<BettiNumbers>
computePrefixBettiNumbers (const FilteredComplex& complex,
                           const PersistenceResult& result);

/** \brief Betti numbers of the subcomplex of simplices with value <= \a radius,
 * from the marks of \a result (Eq. 5.1).
 * \throws pcl::BadArgumentException when \a result lacks marks for \a complex, or
 * \a radius is NaN
 */
BettiNumbers
computeBettiNumbersAt (const FilteredComplex& complex,
                       const PersistenceResult& result,
                       double radius);

} // namespace tda
} // namespace pcl
