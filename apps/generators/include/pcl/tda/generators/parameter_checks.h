#pragma once

// Checks of the parameters of the synthetic cloud generators, shared by them: each
// throws pcl::BadArgumentException with a message naming the generator and the
// parameter.

namespace pcl {
namespace tda {

/** \brief Throws pcl::BadArgumentException "<name>: <what> must be finite and > 0"
 * unless \a value is finite and positive. */
void
checkLength (float value, const char* name, const char* what);

/** \brief Throws pcl::BadArgumentException "<name>: <what> must be finite and >= 0"
 * unless \a value is finite and not negative. */
void
checkNonNegative (float value, const char* name, const char* what);

} // namespace tda
} // namespace pcl
