#include <pcl/tda/apps/display_connection.h>

#include <X11/Xlib.h>

#include <cstdlib>

namespace pcl {
namespace tda {

DisplayConnection::DisplayConnection()
{
  const char* name = std::getenv ("DISPLAY");
  if (name == nullptr || *name == '\0') {
    problem_ = "DISPLAY is not set";
    return;
  }
  display_ = XOpenDisplay (nullptr);
  if (display_ == nullptr)
    problem_ = std::string ("cannot open the X display '") + name + "'";
}

DisplayConnection::~DisplayConnection()
{
  if (display_ != nullptr)
    XCloseDisplay (display_);
}

} // namespace tda
} // namespace pcl
