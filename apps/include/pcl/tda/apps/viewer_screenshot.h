#pragma once

#include <vtkRenderWindow.h>

#include <string>

namespace pcl {
namespace tda {

/** \brief Renders \a window and saves what it shows as a PNG picture of its size
 * (RGBImage::savePNG(), atomically): the viewer's -screenshot, which works for an
 * off-screen window too.
 * \throws pcl::IOException when the file cannot be written */
void
saveWindowPicture (vtkRenderWindow* window, const std::string& path);

} // namespace tda
} // namespace pcl
