#include <pcl/tda/generators/parameter_checks.h>
#include <pcl/exceptions.h>

#include <cmath>

namespace pcl {
namespace tda {
namespace {

/** Throws "<name>: <what> must be finite and <range>, not <value>" unless valid. */
void
check (bool valid, float value, const char* name, const char* what, const char* range)
{
  if (!valid)
    PCL_THROW_EXCEPTION (pcl::BadArgumentException,
                         name << ": " << what << " must be finite and " << range
                              << ", not " << value);
}

} // namespace

void
checkLength (float value, const char* name, const char* what)
{
  check (std::isfinite (value) && value > 0.0f, value, name, what, "> 0");
}

void
checkNonNegative (float value, const char* name, const char* what)
{
  check (std::isfinite (value) && value >= 0.0f, value, name, what, ">= 0");
}

} // namespace tda
} // namespace pcl
