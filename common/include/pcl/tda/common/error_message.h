#pragma once

#include <exception>
#include <string>

namespace pcl {
namespace tda {

/** \brief The description of an error for a user: the message of \a error without
 * the function, file and line that PCL_THROW_EXCEPTION puts before it. */
inline std::string
errorMessage (const std::exception& error)
{
  const std::string message = error.what();
  const auto separator = message.find (" : ");
  if (separator != std::string::npos)
    return message.substr (separator + 3);
  return message.compare (0, 2, ": ") == 0 ? message.substr (2) : message;
}

} // namespace tda
} // namespace pcl
