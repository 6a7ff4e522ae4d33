#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace pcl {
namespace tda {

/** \brief A console progress bar for long work in the tools: call update() as
 * often as you like, it redraws only when the shown percentage changes, and only
 * when its stream is a terminal (so logs and pipes stay clean). */
class ProgressBar {
public:
  explicit ProgressBar (std::string label, std::FILE* stream = stderr);
  ~ProgressBar();

  /** \brief Reports that \a done of \a total units of work are finished. */
  void
  update (std::size_t done, std::size_t total);

  /** \brief Draws the bar at 100% and ends its line. */
  void
  finish ();

private:
  std::string label_;
  std::FILE* stream_;
  bool enabled_;
  int shown_percent_ = -1;
  bool finished_ = false;
};

} // namespace tda
} // namespace pcl
