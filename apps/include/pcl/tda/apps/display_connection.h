#pragma once

#include <string>

// Xlib's connection type, by name only.
struct _XDisplay;

namespace pcl {
namespace tda {

/** \brief A connection to the X display, opened to check that there is one before
 * VTK opens its window (VTK aborts the process when it finds none), and held while
 * the viewer runs: an X server that lost its last client resets, and would refuse
 * VTK's connection meanwhile (Xvfb, as xvfb-run starts it). */
class DisplayConnection {
public:
  /** \brief Opens the display that DISPLAY names. */
  DisplayConnection();

  ~DisplayConnection();

  DisplayConnection (const DisplayConnection&) = delete;
  DisplayConnection&
  operator= (const DisplayConnection&) = delete;

  /** \brief Why there is no connection ("DISPLAY is not set", ...); "" when there is
   * one. */
  const std::string&
  problem () const
  {
    return problem_;
  }

private:
  _XDisplay* display_ = nullptr;
  std::string problem_;
};

} // namespace tda
} // namespace pcl
