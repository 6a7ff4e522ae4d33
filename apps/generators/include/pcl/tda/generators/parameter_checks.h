#pragma once

// Checks of the parameters of the synthetic cloud generators, shared by them: each
// throws pcl::BadArgumentException with a message naming the generator and the
// parameter.

#include <pcl/exceptions.h>

#include <sstream>

namespace pcl {
namespace tda {

/** \brief Throws pcl::BadArgumentException "<name>: <message>" unless \a valid; the
 * message is the \a parts written one after the other to a stream. */
template <typename... Parts>
void
checkParameter (bool valid, const char* name, const Parts&... parts)
{
  if (valid)
    return;
  std::ostringstream text;
  (text << ... << parts);
  PCL_THROW_EXCEPTION (pcl::BadArgumentException, name << ": " << text.str());
}

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
