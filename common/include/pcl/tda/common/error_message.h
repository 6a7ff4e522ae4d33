#pragma once

#include <exception>
#include <new>
#include <string>

namespace pcl {
namespace tda {

/** \brief The description of an error for a user: the message of \a error without
 * the function, file and line that PCL_THROW_EXCEPTION puts before it; for
 * std::bad_alloc, what ran out. */
inline std::string
errorMessage (const std::exception& error)
{
  if (dynamic_cast<const std::bad_alloc*> (&error))
    return "out of memory (under a memory limit of the system, e.g. ulimit -v?)";
  const std::string message = error.what();
  const auto separator = message.find (" : ");
  if (separator != std::string::npos)
    return message.substr (separator + 3);
  return message.compare (0, 2, ": ") == 0 ? message.substr (2) : message;
}

} // namespace tda
} // namespace pcl
